#pragma once
// The state a time integrator steps from and the step it holds pending
// (time_integrator.hpp): (t, q, v, a) now, at the start of the last accepted step (for
// dense output), and at the end of the last converged attempt. HHT, the IRK integrator and
// the PETSc TS bridge keep this the same way; what each carries beyond it (forces, stages,
// the TS object) stays its own.
//
// Two pieces, for two kinds of user:
//   StepState — the bookkeeping (start, pending, accept, Hermite dense output). An
//     integrator's implementation works on these vectors throughout an attempt, so it holds
//     the StepState by reference and calls it, rather than reaching into a base class;
//   StepStateIntegrator — a base between TimeIntegrator and the concrete integrators that
//     owns the StepState and answers TimeIntegrator's seven state accessors once, since
//     they are the same for every integrator (forwarding them from each one would repeat
//     the seven declarations and definitions three times).
// What differs (set_state's acceleration, the attempt, accept's extra state, the dense
// output of collocation methods) stays in the integrators, which call StepState for the
// common part.
#include <petscvec.h>

#include <functional>

#include "catena/assembly/petsc_handle.hpp"
#include "catena/assembly/second_order_system.hpp"
#include "catena/solvers/time/time_integrator.hpp"

namespace catena::solvers {

// Fills `a` with the acceleration at (t, q, v).
using AccelerationSolve = std::function<void(double t, Vec q, Vec v, Vec a)>;

// The one-off consistent acceleration M a = −f(t, q, v) of `system` (with constraints also
// λ, written into q: consistent_acceleration.hpp), for StepState::start. Collective when
// called.
AccelerationSolve consistent_acceleration_of(assembly::SecondOrderSystem& system, Mat mass);

class StepState {
 public:
  // Collective. Nine vectors of the system's layout.
  explicit StepState(const assembly::SecondOrderSystem& system);

  // Not collective. Where an unknown acceleration (see start and set_pending) comes from
  // when it is first needed. Without it every acceleration must be known.
  void set_lazy_acceleration(AccelerationSolve solve) { lazy_acceleration_ = std::move(solve); }

  // Collective. The state at t: q, v copied, and a if given; with a null, `fill` computes
  // it now from the copied q and v or, if `fill` is empty, it stays unknown until first
  // needed. The previous state becomes the same; nothing is pending.
  void start(double t, Vec q, Vec v, Vec a, const AccelerationSolve& fill);

  // Not collective. The pending vectors hold a converged step that ends at t_end; its
  // acceleration is in pending_a() or, if not `acceleration_known`, is computed when first
  // needed after accept().
  void set_pending(double t_end, bool acceleration_known = true);
  // Not collective. No step pending (a failed attempt, or one about to overwrite them).
  void discard_pending() { pending_valid_ = false; }
  bool has_pending() const { return pending_valid_; }

  // Not collective. The pending step becomes the current state and the current state the
  // previous one (the vectors are swapped, not copied). Throws std::logic_error without a
  // converged step pending; `integrator` names the caller in the message.
  void accept(const char* integrator);

  // Collective. q and v at t by cubic Hermite interpolation over the last accepted step
  // [previous_time(), time()] (q from q and v at both ends, v from v and a), or the current
  // state where that step has zero length (after start()). Either output may be null.
  void interpolate(double t, Vec q, Vec v);
  // Collective. The same at θ ∈ [0, 1] of a step of length h, for an integrator that keeps
  // its own step length.
  void interpolate_hermite(double theta, double h, Vec q, Vec v);
  // Collective. Copies the current q and v (either may be null).
  void copy_current(Vec q, Vec v) const;

  double time() const { return t_; }
  double previous_time() const { return t_prev_; }
  Vec q() const { return q_.get(); }
  Vec v() const { return v_.get(); }
  // Collective if the acceleration is unknown (then computed here).
  Vec a();
  Vec previous_q() const { return q_prev_.get(); }
  Vec previous_v() const { return v_prev_.get(); }
  Vec previous_a();  // Collective if unknown, as a()
  Vec pending_q() const { return q_pending_.get(); }
  Vec pending_v() const { return v_pending_.get(); }
  Vec pending_a() const { return a_pending_.get(); }

 private:
  // a, computed at (t, q, v) first unless `known`.
  Vec known_acceleration(bool& known, double t, Vec q, Vec v, Vec a);

  double t_ = 0.0, t_prev_ = 0.0, t_pending_ = 0.0;
  VecHandle q_, v_, a_, q_prev_, v_prev_, a_prev_, q_pending_, v_pending_, a_pending_;
  bool a_known_ = true, a_prev_known_ = true, a_pending_known_ = true;
  bool pending_valid_ = false;
  AccelerationSolve lazy_acceleration_;
};

class StepStateIntegrator : public TimeIntegrator {
 public:
  double time() const override { return state_.time(); }
  double previous_time() const override { return state_.previous_time(); }
  Vec q() const override { return state_.q(); }
  Vec v() const override { return state_.v(); }
  // Collective where the integrator leaves the acceleration unknown (StepState::a).
  Vec a() const override { return state_.a(); }
  Vec pending_q() const override { return state_.pending_q(); }
  Vec pending_v() const override { return state_.pending_v(); }

 protected:
  // Collective (creates the state's vectors).
  explicit StepStateIntegrator(const assembly::SecondOrderSystem& system) : state_(system) {}
  StepStateIntegrator(const StepStateIntegrator&) = delete;
  StepStateIntegrator& operator=(const StepStateIntegrator&) = delete;
  StepState& step_state() const { return state_; }

 private:
  // mutable: a() computes an acceleration left unknown (the PETSc TS bridge's first-order
  // types) when first asked.
  mutable StepState state_;
};

}  // namespace catena::solvers
