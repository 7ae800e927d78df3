#pragma once
// Where a pantograph's contact point is on the wire it runs under (model::MovingContact),
// shared by the penalty contact (pantograph_contact.hpp) and the bilateral one
// (bilateral_contact.hpp). The point moves along the wire's path at the pantograph's speed,
// s(t) = start + speed·t, and lies on the path element holding s, whose position there is
//   r_w = S1 r_A + S2 r_A,x + S3 r_B + S4 r_B,x    (elements/hermite.hpp).
// Over the 15 DOFs x = [r_head, r_A, r_A,x, r_B, r_B,x] the gap along `up` is
//   δ = (r_head − r_w)·up = N·x,   δ̇ = N·ẋ + D·x,   δ̈ = N·ẍ + 2 D·ẋ + E·x,
//   D = −speed (dS/ds)·up,   E = −speed² (d²S/ds²)·up     (the point slides along the wire).
//
// A contact's matrix pattern couples the head with every DOF of the part of the path it may
// reach within the analysis (model::contact_reach), not with the whole path.
#include <cstddef>
#include <vector>

#include "catena/couplings/coupling.hpp"
#include "catena/model/model.hpp"
#include "catena/model/path_stations.hpp"

namespace catena::couplings {

class ContactPath {
 public:
  // Appends the DOFs of the reach's nodes (r, r_x: 6 each, ascending node index) to `dofs`.
  ContactPath(const model::Model& model, const model::MovingContact& contact,
              std::vector<DofKey>& dofs);

  double position(double t) const { return contact_.start + contact_.speed * t; }
  // A moving window (model::CatenaryWindow) moved the wire's state back by `ds` along the
  // path: the contact point moves back with it.
  void move_back(double ds) { contact_.start -= ds; }
  bool on_path(double t) const { return stations_.contains(position(t)); }
  // The positions in dofs of the 12 wire DOFs of the element holding s(t) (on the path),
  // appended to `positions`.
  void element_dofs(double t, std::vector<int>& positions) const;
  // N, D and E (may be null) over the 15 active DOFs at time t (on the path).
  void directions(double t, double* N, double* D, double* E = nullptr) const;
  // First and one-past-last positions in dofs of the reach's DOFs.
  int first_dof() const { return first_; }
  int end_dof() const { return end_; }

  static constexpr int kActive = 15;  // head (3) + the wire element's r_A, r_A,x, r_B, r_B,x

 private:
  // The path element holding the contact point at t; an Error if it lies beyond the reach
  // the pattern was made for (a time past analysis.duration).
  std::size_t element_in_reach(double t) const;

  model::MovingContact contact_;
  model::PathStations stations_;
  model::PathReach reach_;
  std::vector<int> element_a_, element_b_;  // per path element: position of node A/B's DOFs
                                            // (−1 outside the reach)
  int first_ = 0, end_ = 0;
};

}  // namespace catena::couplings
