#pragma once
// The last line of defence of a dynamic run against output that is not a result: every
// sampled state is checked before it is written, and a run whose state is not finite, or
// whose motion has grown beyond anything the scene can do, stops with a NumericalError
// (exit 3) that names the time, the unknown and the cause, instead of writing it.
//
// "Beyond anything the scene can do": a node further from its mesh position than
// kReachFactor times the model's size (the diagonal of the box around its mesh nodes,
// plus the travel of prescribed motions), or an ANCF gradient changed by more than
// kReachFactor (a unit tangent stretched tenfold). A structure that is supported (the
// scene reader refuses free bodies) cannot get there by its own motion: a pendulum's node
// moves at most twice its length. Such growth is an unstable step — energy growth from a
// method pushed past its stability limit (docs/accuracy.md, "Where each method stops
// working") — and every later sample would be worse. Growth below the bound is the
// business of the accuracy checks (the contact-force resolution warning, the error
// estimate), not of this guard.
//
// A slider that runs past either end of its path (model::Slider) has left it: a NumericalError that
// names the slider and the time, whatever the step.
//
// Most integrators already fail a step whose residual is not finite (the step is then
// cut); the guard also covers those that do not iterate (the modal model, the linearly
// implicit step) and the states the dense output interpolates.
#include <petscvec.h>

#include <string>
#include <vector>

#include "catena/assembly/second_order_system.hpp"

namespace catena::solvers {

class StateGuard {
 public:
  static constexpr double kReachFactor = 10.0;

  // Collective (the reference state is a vector). `t_end`: the run's end, for the travel of
  // prescribed motions; `dt`: the step, named in the message.
  StateGuard(const assembly::SecondOrderSystem& system, double t_end, double dt);

  // Not collective. The model's size and the bound on a node's distance from its mesh
  // position, in metres.
  double model_size() const { return size_; }
  double position_bound() const { return position_bound_; }

  // Collective. Throws NumericalError (prefixed with `who`, the integrator's name) if q or
  // v at time t holds a value that is not finite or beyond the bounds above.
  void check(const std::string& who, double t, Vec q, Vec v) const;

  // Collective (a no-op without sliders). Throws NumericalError if a slider at q has left its path:
  // for every accepted step, so that a slider is stopped where it leaves, not a sample
  // later.
  void check_sliders(double t, Vec q) const;
  // Not collective (the same on every rank). Whether the model has sliders to check.
  bool watches_sliders() const;

  // Not collective. The end of every such message: which step failed, what to do (also
  // for the checks of step records outside the guard).
  std::string unstable_step() const;

 private:
  const assembly::SecondOrderSystem& system_;
  double dt_ = 0.0, size_ = 0.0, position_bound_ = 0.0;
  VecHandle reference_;
  // Per owned entry: the largest change from the reference allowed (0: not checked, the
  // Lagrange multipliers, which are forces, and sliders' arc lengths, checked below).
  std::vector<double> bound_;
  // The owned sliders' arc lengths: entry (owned index), slider (index into model.sliders)
  // and the path's length, m. A slider past either end of its path has left it.
  struct SliderEntry {
    std::size_t entry;
    int slider;
    double length;
  };
  std::vector<SliderEntry> sliders_;
  // Collective. Throws NumericalError if a slider has left its path (`slides`: the arc lengths of
  // sliders_, in its order).
  void check_sliders(double t, const std::vector<double>& slides) const;
};

}  // namespace catena::solvers
