#pragma once
// Any element linearised about a state q₀ (normally the static equilibrium):
//
//   f(q, v) = f₀ + K₀ (q − q₀) + C₀ v ,   K = K₀ ,   C = C₀ ,   M unchanged,
//
// with f₀, K₀, C₀ the wrapped element's force, tangent stiffness (stress stiffening
// included) and damping matrix at (q₀, v = 0) at the end of the load path. This is the
// linear structural dynamics of small motions about the equilibrium (Géradin & Rixen,
// "Mechanical Vibrations", 3rd ed. 2015, §2.6): the element's matrices are evaluated once,
// its force is a matrix–vector product, and its Jacobian never changes, so an integrator
// that keeps its factorisation while the Jacobian is unchanged factors once for the run.
// Section results are the wrapped element's at the current state (for output).
#include <memory>
#include <span>
#include <vector>

#include "catena/elements/element.hpp"

namespace catena::elements {

class Linearized final : public Element {
 public:
  // q0: the state to linearise about, node-major, n_dofs() values.
  Linearized(std::unique_ptr<Element> inner, std::span<const double> q0);

  int n_nodes() const override { return inner_->n_nodes(); }
  int dofs_per_node() const override { return inner_->dofs_per_node(); }
  void evaluate(const LocalState& s, Request r, LocalOutput out) const override;
  bool has_damping() const override { return inner_->has_damping(); }
  void mass(double* M) const override { inner_->mass(M); }
  SectionResult section_result(const LocalState& s) const override {
    return inner_->section_result(s);
  }

 private:
  std::unique_ptr<Element> inner_;
  std::vector<double> q0_, f0_, K0_, C0_;
};

}  // namespace catena::elements
