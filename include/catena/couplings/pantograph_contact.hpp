#pragma once
// The penalty contact between a pantograph head and the wire it runs under
// (model::MovingContact; docs/formulation.md, "Moving contact"). The contact point moves
// along the wire's path (couplings/contact_path.hpp: N, D over the 15 DOFs
// x = [r_head, r_A, r_A,x, r_B, r_B,x]):
//   penetration  δ = (r_head − r_w)·up = N·x,
//   its rate     δ̇ = N·ẋ + D·x,
//   force        F = max(0, k δ + c δ̇) if δ > 0, else 0   (compression only),
//   f = F N,  K = N (k N + c D)ᵀ,  C = c N Nᵀ              (while F > 0; else 0).
// The head pushes the wire up and the wire pushes the head down, both through N.
//
// One rank evaluates a contact (the owner of the head node). Its matrix pattern couples the
// head with every DOF of the part of the path it may reach within the analysis
// (model::contact_reach); the path's own entries belong to the path elements (which
// therefore must be cable or beam elements).
#include <vector>

#include "catena/couplings/contact_path.hpp"
#include "catena/couplings/coupling.hpp"
#include "catena/model/model.hpp"

namespace catena::couplings {

class PantographContact final : public Coupling {
 public:
  // `index`: into model.contacts.
  PantographContact(const model::Model& model, int index);

  bool dense() const override { return false; }
  void pattern(std::vector<std::pair<int, int>>& entries) const override;
  bool acts_on_all() const override { return false; }
  // The 15 DOFs [r_head, r_A, r_A,x, r_B, r_B,x] of the path element holding s(t); none
  // while the contact point is off its path.
  void active_dofs(double t, std::vector<int>& positions) const override;
  void evaluate(const CouplingState& s, double* f, std::span<const MatrixRequest> m,
                Scratch& scratch) const override;
  bool has_damping() const override { return contact_.damping != 0.0; }
  PatchRole patch_role() const override { return PatchRole::at_patch_time; }

  int index() const { return index_; }
  // Contact point's arc length along its path at t, m.
  double position(double t) const { return path_.position(t); }
  bool on_path(double t) const { return path_.on_path(t); }
  // The wire's state moved back by ds along the path (ContactPath::move_back).
  void move_back_along_path(double ds) { path_.move_back(ds); }
  // Force (N, ≥ 0) and penetration δ (m) at s (its active DOFs; on the path).
  double force(const CouplingState& s, double* penetration = nullptr) const;

 private:
  int index_;
  model::MovingContact contact_;
  ContactPath path_;
};

}  // namespace catena::couplings
