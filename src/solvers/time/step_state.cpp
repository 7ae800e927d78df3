#include "catena/solvers/time/step_state.hpp"

#include <stdexcept>
#include <string>
#include <utility>

#include "catena/assembly/petsc_call.hpp"
#include "catena/solvers/time/consistent_acceleration.hpp"
#include "catena/solvers/time/hermite_interpolation.hpp"

namespace catena::solvers {

AccelerationSolve consistent_acceleration_of(assembly::SecondOrderSystem& system, Mat mass) {
  return [&system, mass](double t, Vec q, Vec v, Vec a) {
    consistent_acceleration(system, mass, t, q, v, a);
  };
}

StepState::StepState(const assembly::SecondOrderSystem& system) {
  for (VecHandle* v :
       {&q_, &v_, &a_, &q_prev_, &v_prev_, &a_prev_, &q_pending_, &v_pending_, &a_pending_})
    *v = system.create_vector();
}

void StepState::start(double t, Vec q, Vec v, Vec a, const AccelerationSolve& fill) {
  t_ = t_prev_ = t;
  CATENA_PETSC(VecCopy(q, q_.get()));
  CATENA_PETSC(VecCopy(v, v_.get()));
  a_known_ = true;
  if (a)
    CATENA_PETSC(VecCopy(a, a_.get()));
  else if (fill)
    fill(t, q_.get(), v_.get(), a_.get());
  else
    a_known_ = false;
  for (auto [from, to] : {std::pair{&q_, &q_prev_}, {&v_, &v_prev_}, {&a_, &a_prev_}})
    CATENA_PETSC(VecCopy(from->get(), to->get()));
  a_prev_known_ = a_known_;
  pending_valid_ = false;
}

void StepState::set_pending(double t_end, bool acceleration_known) {
  t_pending_ = t_end;
  a_pending_known_ = acceleration_known;
  pending_valid_ = true;
}

void StepState::accept(const char* integrator) {
  if (!pending_valid_)
    throw std::logic_error(std::string(integrator) + "::accept without a converged step");
  std::swap(q_prev_, q_);
  std::swap(v_prev_, v_);
  std::swap(a_prev_, a_);
  std::swap(q_, q_pending_);
  std::swap(v_, v_pending_);
  std::swap(a_, a_pending_);
  a_prev_known_ = a_known_;
  a_known_ = a_pending_known_;
  t_prev_ = t_;
  t_ = t_pending_;
  pending_valid_ = false;
}

Vec StepState::known_acceleration(bool& known, double t, Vec q, Vec v, Vec a) {
  if (!known) {
    lazy_acceleration_(t, q, v, a);
    known = true;
  }
  return a;
}

Vec StepState::a() { return known_acceleration(a_known_, t_, q_.get(), v_.get(), a_.get()); }

Vec StepState::previous_a() {
  return known_acceleration(a_prev_known_, t_prev_, q_prev_.get(), v_prev_.get(), a_prev_.get());
}

void StepState::copy_current(Vec q, Vec v) const {
  if (q) CATENA_PETSC(VecCopy(q_.get(), q));
  if (v) CATENA_PETSC(VecCopy(v_.get(), v));
}

void StepState::interpolate(double t, Vec q, Vec v) {
  const double h = t_ - t_prev_;
  if (h <= 0.0) {
    copy_current(q, v);
    return;
  }
  interpolate_hermite((t - t_prev_) / h, h, q, v);
}

void StepState::interpolate_hermite(double theta, double h, Vec q, Vec v) {
  if (q) hermite_interpolate(theta, h, q_prev_.get(), v_prev_.get(), q_.get(), v_.get(), q);
  if (v) {
    Vec a0 = previous_a();  // before a(): lazy solves (forces, counters) in a fixed order
    hermite_interpolate(theta, h, v_prev_.get(), a0, v_.get(), a(), v);
  }
}

}  // namespace catena::solvers
