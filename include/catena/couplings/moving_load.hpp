#pragma once
// A constant force F travelling along a path of cable or beam elements at constant speed
// (model::MovingLoad): at time t it acts at arc length s = start + speed (t − start_time)
// on the element holding s, whose position there is
//   r(x) = S1 r_A + S2 r_A,x + S3 r_B + S4 r_B,x        (elements/hermite.hpp),
// so its generalised force is Sᵀ F, and f (which carries −f_ext) receives −Sᵀ F.
// f depends on t only: the coupling adds nothing to the Newton matrix.
//
// One rank evaluates each path element (its owner): a MovingLoad holds the path elements
// `evaluated` lists and acts only while s lies on one of them.
#include <vector>

#include "catena/couplings/coupling.hpp"
#include "catena/model/model.hpp"
#include "catena/model/path_stations.hpp"

namespace catena::couplings {

class MovingLoad final : public Coupling {
 public:
  // `evaluated[i]`: whether this coupling evaluates the load on path element i.
  MovingLoad(const model::Model& model, const model::MovingLoad& load,
             const std::vector<bool>& evaluated);

  bool dense() const override { return false; }
  void pattern(std::vector<std::pair<int, int>>& entries) const override { entries.clear(); }
  bool acts_on_all() const override { return false; }
  // The 12 DOFs [r_A, r_A,x, r_B, r_B,x] of the element holding s(t), if evaluated here.
  void active_dofs(double t, std::vector<int>& positions) const override;
  void evaluate(const CouplingState& s, double* f, std::span<const MatrixRequest> m,
                Scratch& scratch) const override;
  PatchRole patch_role() const override { return PatchRole::state_independent; }

  // Arc length of the load at time t, m; off the path before start_time.
  double position(double t) const { return load_.start + load_.speed * (t - load_.start_time); }

 private:
  // The path element holding the load at t, or −1 (off the path, or not evaluated here).
  int element_at(double t) const;

  model::MovingLoad load_;
  model::PathStations stations_;
  std::vector<int> first_dof_;  // per path element: position of its 12 DOFs in dofs(), or −1
};

}  // namespace catena::couplings
