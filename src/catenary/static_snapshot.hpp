#pragma once
// A static solve whose results every rank holds in model order: node positions, element
// axial forces and support reactions. For the catenary procedures that iterate on
// whole-model quantities (shape finding) rather than on distributed vectors; the gather
// costs O(n_nodes + n_elements) per solve.
#include <mpi.h>

#include <vector>

#include "catena/core/vec3.hpp"
#include "catena/model/model.hpp"
#include "catena/solvers/statics/static_solver.hpp"

namespace catena::catenary::detail {

struct StaticSnapshot {
  std::vector<Vec3> positions;      // m, per node
  std::vector<double> axial_force;  // N, per element, at its mid-point (tension > 0)
  std::vector<Vec3> reactions;      // N, per node: force of its supports on it (0 if none)
  solvers::StaticReport report;
};

// Collective. Solves `model`'s static equilibrium from its reference configuration
// (StaticSolver with model.static_options) and gathers the results on every rank. Each
// value comes from the one rank that owns it, so every rank holds identical numbers and
// iterations built on them stay in step. Throws what StaticSolver throws.
StaticSnapshot solve_static_snapshot(MPI_Comm comm, const model::Model& model);

// Not collective. Σ N_e L_e / Σ L_e over `elements` (L_e: mesh length), N.
double mean_axial_force(const model::Model& model, const StaticSnapshot& snapshot,
                        const std::vector<int>& elements);

}  // namespace catena::catenary::detail
