#pragma once
// What a time integrator and the step-control driver carry from one accepted step to the
// next beyond the state (t, q, v, a): the predictor's history, the point at which the
// reused tangent was evaluated, its age and the factorisation's freshness, the step-size
// controller's next step, work counters. A checkpoint stores it (io/checkpoint.hpp), so
// that a restart on the same ranks continues bit for bit as the uninterrupted run.
//
// A matrix is never stored: the owner stores the point and coefficients it was evaluated
// at and, on restore, evaluates and factors it there again (the same deterministic
// assembly at the same point gives the same matrix, and the same factorisation on the
// same ranks). Vectors are in the DOF layout of SecondOrderSystem::create_vector(); the
// checkpoint stores them node-indexed, so another rank count can restore them too (then to
// round-off only, which the Newton tolerance absorbs). Names are the owner's business,
// prefixed by it ("hht.", "irk.", "newton.", "driver.").
#include <petscvec.h>

#include <cstdint>
#include <map>
#include <string>

namespace catena::solvers {

struct ResumeState {
  std::map<std::string, Vec> vectors;  // not owned
  std::map<std::string, double> reals;
  std::map<std::string, std::int64_t> integers;

  bool empty() const { return vectors.empty() && reals.empty() && integers.empty(); }
  // Not collective. The entry `name`; throws catena::Error naming it if it is missing.
  Vec vector(const std::string& name) const;
  double real(const std::string& name) const;
  std::int64_t integer(const std::string& name) const;
};

}  // namespace catena::solvers
