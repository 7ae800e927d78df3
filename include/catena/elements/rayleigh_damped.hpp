#pragma once
// Rayleigh (proportional) damping on top of any element:
//
//   f_d = D v ,   D = α M + β K_ref ,   C += D
//
// with K_ref the element's tangent stiffness in its reference state (the mesh geometry,
// prestrain in place, velocity zero), fixed for the run. This is the classical linear
// viscous damping of structural dynamics (Clough & Penzien): modal damping ratio
// ζ(ω) = α/(2ω) + βω/2 for the modes of the system linearised about the reference state.
// For a taut wire the transverse stiffness is the tension's geometric stiffness, which
// K_ref contains: Kelvin–Voigt damping of the axial strain (AncfCable's damping_time)
// damps stretching only and leaves the transverse waves that matter for contact
// undamped to first order. K_ref rather than the current tangent keeps D constant (no
// damping forces from stiffness changes, no contribution to ∂f/∂q) — the usual choice.
#include <memory>
#include <span>

#include "catena/elements/element.hpp"
#include "catena/elements/matrix_arena.hpp"

namespace catena::elements {

struct RayleighCoefficients {
  double mass = 0.0;       // α, 1/s
  double stiffness = 0.0;  // β, s
};

class RayleighDamped final : public Element {
 public:
  // q_ref: the element's reference state, node-major, n_dofs() values. D is kept in `arena`
  // when given (matrix_arena.hpp: the list's matrices contiguous, in the order it is built),
  // else in an arena of the element's own.
  RayleighDamped(std::unique_ptr<Element> inner, RayleighCoefficients c,
                 std::span<const double> q_ref, std::shared_ptr<MatrixArena> arena = nullptr);

  int n_nodes() const override { return inner_->n_nodes(); }
  int dofs_per_node() const override { return inner_->dofs_per_node(); }
  void evaluate(const LocalState& s, Request r, LocalOutput out) const override;
  void mass(double* M) const override { inner_->mass(M); }
  SectionResult section_result(const LocalState& s) const override {
    return inner_->section_result(s);
  }

  // D = α M + β K_ref, row-major n_dofs()².
  std::span<const double> damping_matrix() const {
    return {D_, static_cast<std::size_t>(n_dofs() * n_dofs())};
  }

 private:
  std::unique_ptr<Element> inner_;
  std::shared_ptr<MatrixArena> arena_;  // holds D_
  double* D_ = nullptr;
};

}  // namespace catena::elements
