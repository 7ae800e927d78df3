#pragma once
// A windowed catenary's move along its line (model::CatenaryWindow): before each step, if
// the first pantograph has passed the start of span behind + period of the window, the
// line's state moves back one period — each node takes the position (less the period's
// length in x), velocity and acceleration of the node one period ahead
// (model::window_state_sources), the nodes of the last period take the static state at
// rest, the pantographs keep theirs — and the pantographs' contact points move back along
// the wire with it. The integrator restarts from the moved state (set_state): a one-step
// method continues as on the line, since the state it holds is the line's around the
// pantographs. Output and statistics add the distance moved (x_offset, arc_offset).
#include <petscvec.h>

#include <vector>

#include "catena/assembly/petsc_handle.hpp"
#include "catena/assembly/second_order_system.hpp"
#include "catena/model/catenary_window.hpp"
#include "catena/solvers/time/transient_solver.hpp"

namespace catena::app {

class WindowMover final : public solvers::StepBoundary {
 public:
  // Collective. `q_line`: the catenary's own static state (window_statics.hpp), which the
  // spans that enter take (copied). The model must have a window.
  WindowMover(assembly::SecondOrderSystem& system, Vec q_line);
  ~WindowMover() override;
  WindowMover(const WindowMover&) = delete;
  WindowMover& operator=(const WindowMover&) = delete;

  void before_step(solvers::TimeIntegrator& integrator) override;

  // Not collective. How many periods the window has moved since t = 0.
  long moves() const { return moves_; }
  // Not collective (call on every rank alike). A restart: the window where the checkpoint
  // left it (the state is the checkpoint's; the contact points move with the count).
  void restore(long moves);
  // m: how far the window's x has moved along the line, and the line's contact-wire path
  // position of the window path's start (what turns the window's positions into the line's).
  double x_offset() const;
  double arc_offset() const;

 private:
  // Collective. `to` takes from `from` each owned row of a node with an image one period
  // ahead (its image's row), and the constraints' multipliers; positions: x moved back too.
  void move(Vec from, Vec to, bool positions) const;

  assembly::SecondOrderSystem& system_;
  VecHandle q_line_, q_, v_, a_;
  VecScatter scatter_ = nullptr;  // each row from its image's row
  std::vector<PetscInt> x_rows_;  // local rows of the positions' x taken from another node
  // Local rows whose image holds them fixed, and the values they take (at rest).
  std::vector<PetscInt> fixed_rows_;
  std::vector<double> fixed_values_;
  long moves_ = 0;
  bool announced_ = false;
};

}  // namespace catena::app
