#include "resume_checkpoint.hpp"

#include <cstdio>

#include "catena/assembly/state_view.hpp"

namespace catena::app {

io::ResumeRows resume_rows(const assembly::SecondOrderSystem& system,
                           const solvers::TimeIntegrator& integrator,
                           const std::optional<solvers::DriverState>& driver) {
  solvers::ResumeState state;
  integrator.save_resume_state(state);
  if (driver) solvers::save_driver_state(*driver, state);
  io::ResumeRows out;
  for (const auto& [name, vector] : state.vectors)
    assembly::StateView(system).owned_node_rows(vector, out.rows[name], out.multipliers[name]);
  out.reals = std::move(state.reals);
  out.integers = std::move(state.integers);
  return out;
}

RestoredResumeState::RestoredResumeState(const assembly::SecondOrderSystem& system,
                                         const io::ResumeRows& rows) {
  for (const auto& [name, node_rows] : rows.rows) {
    vectors_.push_back(system.create_vector());
    assembly::StateView(system).set_from_node_rows(vectors_.back().get(), node_rows,
                                                   rows.multipliers.at(name));
    state_.vectors[name] = vectors_.back().get();
  }
  state_.reals = rows.reals;
  state_.integers = rows.integers;
}

std::optional<solvers::DriverState> restore_resume_state(const assembly::SecondOrderSystem& system,
                                                         solvers::TimeIntegrator& integrator,
                                                         const io::Checkpoint& checkpoint) {
  const RestoredResumeState restored(system, checkpoint.resume);
  integrator.restore_resume_state(restored.state());
  return solvers::restore_driver_state(restored.state());
}

// Not collective (rank 0). Says when a restart will not continue bit for bit.
void print_restart_exactness(const io::Checkpoint& c, const solvers::TimeIntegrator& integrator,
                             int ranks) {
  if (!integrator.resumes_exactly())
    std::printf(
        "restart: %s keeps no step-to-step state in the checkpoint: the run agrees "
        "with an uninterrupted one to the method's accuracy, not bit for bit\n",
        integrator.name().c_str());
  else if (c.resume.empty())
    std::printf(
        "restart: the checkpoint holds no solver state (an older format): Newton "
        "starts afresh, so the run agrees with an uninterrupted one to Newton's "
        "tolerance, not bit for bit\n");
  else if (c.facts.ranks != ranks)
    std::printf(
        "restart: checkpoint written on %d ranks, continuing on %d: the run agrees "
        "with an uninterrupted one to Newton's tolerance, not bit for bit\n",
        c.facts.ranks, ranks);
}

}  // namespace catena::app
