#pragma once
// A pantograph's contact held by a Lagrange multiplier instead of a penalty spring
// (`contact: {type: bilateral}`; docs/formulation.md, "Bilateral contact"): the head stays on
// the wire, whatever the force,
//   g(q, t) = (r_head − r_w(s(t)))·up = N(t)·x = 0                       (1 equation)
// over [λ, r_head (3), then the reach's wire DOFs] (couplings/contact_path.hpp: N, D, E).
// λ is the contact force: the head rows get λ up (the wire pushes the head down by λ), the
// wire rows −λ S_b up (the head pushes the wire up). A negative λ is the wire pulling the
// head up: where a penalty contact would have lost contact. g is linear in q, but N turns
// with s(t), so G depends on t:
//   β = −∂g/∂t = −D·x,   γ = −(2 D·ẋ + E·x)      (G v = β, G a = γ).
// The contact point must stay on its path through the run (the scene reader checks it).
#include <vector>

#include "catena/couplings/constraint_coupling.hpp"
#include "catena/couplings/contact_path.hpp"
#include "catena/model/model.hpp"

namespace catena::couplings {

class BilateralContact final : public ConstraintCoupling {
 public:
  // `index`: into model.constraints, of type contact.
  BilateralContact(const model::Model& model, int index);

  void pattern(std::vector<std::pair<int, int>>& entries) const override;
  bool acts_on_all() const override { return false; }
  // [λ, r_head, the wire element's r_A, r_A,x, r_B, r_B,x] at s(t).
  void active_dofs(double t, std::vector<int>& positions) const override;
  void evaluate(const CouplingState& s, double* f, std::span<const MatrixRequest> m,
                Scratch& scratch) const override;
  bool linear() const override { return false; }
  void acceleration_target(const CouplingState& s, std::span<double> out) const override;
  void velocity_target(const CouplingState& s, std::span<double> out) const override;

  // Index into model.contacts.
  int contact() const { return contact_; }
  double position(double t) const { return path_.position(t); }
  // The wire's state moved back by ds along the path (ContactPath::move_back).
  void move_back_along_path(double ds) { path_.move_back(ds); }

  static constexpr int kActive = 1 + ContactPath::kActive;

 private:
  int contact_;
  ContactPath path_;
};

}  // namespace catena::couplings
