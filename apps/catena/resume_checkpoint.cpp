#include "resume_checkpoint.hpp"

namespace catena::app {

io::ResumeRows resume_rows(const assembly::SecondOrderSystem& system,
                           const solvers::TimeIntegrator& integrator,
                           const std::optional<solvers::DriverState>& driver) {
  solvers::ResumeState state;
  integrator.save_resume_state(state);
  if (driver) solvers::save_driver_state(*driver, state);
  io::ResumeRows out;
  for (const auto& [name, vector] : state.vectors)
    system.owned_node_rows(vector, out.rows[name], out.multipliers[name]);
  out.reals = std::move(state.reals);
  out.integers = std::move(state.integers);
  return out;
}

RestoredResumeState::RestoredResumeState(const assembly::SecondOrderSystem& system,
                                         const io::ResumeRows& rows) {
  for (const auto& [name, node_rows] : rows.rows) {
    vectors_.push_back(system.create_vector());
    system.set_from_node_rows(vectors_.back().get(), node_rows, rows.multipliers.at(name));
    state_.vectors[name] = vectors_.back().get();
  }
  state_.reals = rows.reals;
  state_.integers = rows.integers;
}

}  // namespace catena::app
