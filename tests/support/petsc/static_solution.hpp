#pragma once
// Solves a model's static equilibrium on `comm` and returns the results gathered on every
// rank in model order, so tests can compare runs on different communicators.
#include <mpi.h>

#include <functional>
#include <vector>

#include "catena/assembly/second_order_system.hpp"
#include "catena/model/model.hpp"
#include "catena/solvers/statics/static_solver.hpp"

namespace catena::test {

struct GatheredStatic {
  std::vector<double> positions;       // 3 per node, model order
  std::vector<double> slopes;          // 3 per node
  std::vector<double> axial_force;     // per element
  std::vector<double> reaction_force;  // 3 per model node (zero where unsupported)
  std::vector<double> reaction_moment;
  solvers::StaticReport report;
  long long n_dofs = 0;
};

// Collective. From the reference along the load path; with `guess` (a function that sets a
// starting state in q, e.g. solvers::set_guess) Newton first tries the whole load from it.
GatheredStatic solve_static(
    MPI_Comm comm, const model::Model& m,
    const std::function<void(const assembly::SecondOrderSystem&, Vec)>& guess = {});

}  // namespace catena::test
