#pragma once
// Between the solvers' step-to-step state (solvers/resume_state.hpp: PETSc vectors in the
// DOF layout, numbers) and a checkpoint's partition-independent form (io::ResumeRows:
// node and multiplier rows), for `catena run --restart` to continue bit for bit.
#include <optional>
#include <vector>

#include "catena/assembly/second_order_system.hpp"
#include "catena/io/checkpoint.hpp"
#include "catena/solvers/time_integrator.hpp"
#include "catena/solvers/transient_solver.hpp"

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

}  // namespace catena::app
