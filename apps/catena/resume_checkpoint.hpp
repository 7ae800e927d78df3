#pragma once
// Between the solvers' step-to-step state (solvers/resume_state.hpp: PETSc vectors in the
// DOF layout, numbers) and a checkpoint's partition-independent form (io::ResumeRows:
// node and multiplier rows), for `catena run --restart` to continue bit for bit.
#include <optional>
#include <vector>

#include "catena/assembly/second_order_system.hpp"
#include "catena/io/checkpoint.hpp"
#include "catena/solvers/time/time_integrator.hpp"
#include "catena/solvers/time/transient_solver.hpp"

namespace catena::app {

// Not collective. The integrator's and the driver's state (none before the first step) as
// this rank's rows of the owned nodes and constraints, and the numbers.
io::ResumeRows resume_rows(const assembly::SecondOrderSystem& system,
                           const solvers::TimeIntegrator& integrator,
                           const std::optional<solvers::DriverState>& driver);

// A checkpoint's resume rows as a solvers::ResumeState, with the vectors it points to.
class RestoredResumeState {
 public:
  // Collective (creates vectors).
  RestoredResumeState(const assembly::SecondOrderSystem& system, const io::ResumeRows& rows);
  const solvers::ResumeState& state() const { return state_; }

 private:
  std::vector<VecHandle> vectors_;
  solvers::ResumeState state_;
};

// Collective. Gives the integrator, its state already set from `checkpoint`, the step-to-step
// state saved with it; returns the driver's (none from an older checkpoint).
std::optional<solvers::DriverState> restore_resume_state(const assembly::SecondOrderSystem& system,
                                                         solvers::TimeIntegrator& integrator,
                                                         const io::Checkpoint& checkpoint);

// Not collective (rank 0). Says when a restart will not continue bit for bit (an
// integrator without resume state, an older checkpoint, another rank count).
void print_restart_exactness(const io::Checkpoint& c, const solvers::TimeIntegrator& integrator,
                             int ranks);

}  // namespace catena::app
