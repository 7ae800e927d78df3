#include "catena/solvers/resume_state.hpp"

#include "catena/core/error.hpp"
#include "catena/solvers/time/time_integrator.hpp"

namespace catena::solvers {
namespace {

template <class Map>
const typename Map::mapped_type& entry(const Map& map, const std::string& name, const char* kind) {
  const auto it = map.find(name);
  if (it == map.end())
    throw Error(std::string("the checkpoint's solver state has no ") + kind + " '" + name +
                "' (written by another version of this integrator)");
  return it->second;
}

}  // namespace

Vec ResumeState::vector(const std::string& name) const { return entry(vectors, name, "vector"); }
double ResumeState::real(const std::string& name) const { return entry(reals, name, "number"); }
std::int64_t ResumeState::integer(const std::string& name) const {
  return entry(integers, name, "integer");
}

void save_own_counters(const IntegratorCounters& c, ResumeState& out) {
  out.integers["counters.steps_accepted"] = c.steps_accepted;
  out.integers["counters.steps_rejected"] = c.steps_rejected;
  out.integers["counters.newton_iterations"] = c.newton_iterations;
  out.integers["counters.newton_failures"] = c.newton_failures;
  out.integers["counters.jacobian_evaluations"] = c.jacobian_evaluations;
}

void restore_own_counters(const ResumeState& in, IntegratorCounters& c) {
  c.steps_accepted = in.integer("counters.steps_accepted");
  c.steps_rejected = in.integer("counters.steps_rejected");
  c.newton_iterations = in.integer("counters.newton_iterations");
  c.newton_failures = in.integer("counters.newton_failures");
  c.jacobian_evaluations = in.integer("counters.jacobian_evaluations");
}

}  // namespace catena::solvers
