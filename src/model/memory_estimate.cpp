#include "catena/model/memory_estimate.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "catena/model/node_kinds.hpp"
#include "catena/model/path_stations.hpp"

namespace catena::model {
namespace {

constexpr double kGiB = 1024.0 * 1024.0 * 1024.0;

// Bytes per item, from the types and measured peaks (docs/scene.md, "Memory").
// The model: a node and an element as stored, plus what the reader keeps while building
// (the id map, the entry each came from) and the allocator's overhead.
constexpr double kReaderBytesPerNode = 64.0;
constexpr double kReaderBytesPerElement = 48.0;
// The assembly's element objects (geometry, section, Gauss-point caches), per element.
constexpr double kAssemblyBytesPerElement = 600.0;
// Work vectors per DOF: the state, its integrator copies, residuals and scratch.
constexpr double kVectorsPerDof = 40.0;
// AIJ storage per non-zero (value and column index), for the tangent, the mass matrix
// and the Newton matrix.
constexpr double kBytesPerNonzero = 12.0;
constexpr double kMatricesPerFactor = 2.0;
// LU factor entries per matrix non-zero (the fill of a banded chain under nested
// dissection, L and U), and MUMPS's integer arrays and working space on top.
constexpr double kFactorFill = 2.0;
constexpr double kMumpsOverhead = 1.5;
// Output: a sample's positions, velocities, slopes (9 per node) and axial forces (1 per
// element), twice (the rows and HDF5's staging), and the mesh tables.
constexpr double kOutputValuesPerNode = 2.0 * 9.0 + 4.0;
constexpr double kOutputValuesPerElement = 2.0 + 3.0;

}  // namespace

ProblemSize problem_size(const Model& model) {
  ProblemSize size;
  size.nodes = static_cast<std::int64_t>(model.nodes.size());
  size.elements = static_cast<std::int64_t>(model.elements.size());
  const std::vector<int> dofs = all_node_dofs(model);
  for (const int d : dofs) {
    size.dofs += d;
    size.matrix_nonzeros += static_cast<std::int64_t>(d) * d;  // the node's diagonal block
  }
  // Each element couples its nodes' blocks (two-node elements: the two off-diagonal ones).
  for (const ElementDesc& e : model.elements)
    for (std::size_t i = 0; i < e.nodes.size(); ++i)
      for (std::size_t j = 0; j < e.nodes.size(); ++j)
        if (i != j)
          size.matrix_nonzeros += static_cast<std::int64_t>(dofs[e.nodes[i]]) * dofs[e.nodes[j]];
  // Multipliers: a row and a column each, against up to two node blocks (a joint's two
  // bodies).
  const auto multipliers = static_cast<std::int64_t>(total_multipliers(model));
  size.dofs += multipliers;
  size.matrix_nonzeros += 4 * multipliers * kMaxBlockUnknowns;
  // A pantograph head is coupled to every node of the part of its path it can reach
  // (couplings/pantograph_contact.hpp).
  for (const MovingContact& c : model.contacts) {
    const std::vector<int>& path = model.paths[static_cast<std::size_t>(c.path)].elements;
    const PathReach reach = contact_reach(model, c, path_stations(model, path));
    if (!reach.empty)
      size.matrix_nonzeros += 2 * 3 * 6 * static_cast<std::int64_t>(reach.last - reach.first + 2);
  }
  // A slider's multipliers and s are coupled to every node of its path (r, r_x: 6 each).
  for (const Slider& slider : model.sliders) {
    const std::vector<int>& path = model.paths[static_cast<std::size_t>(slider.path)].elements;
    size.matrix_nonzeros += 2 * 4 * 6 * static_cast<std::int64_t>(path.size() + 1);
  }
  size.factor_multiple = integrator_factor_multiple(model);
  return size;
}

double integrator_factor_multiple(const Model& model) {
  if (model.analysis != AnalysisType::dynamic) return 2.0;  // tangent + stability LDLᵀ
  const IntegratorOptions& in = model.dynamic_options.integrator;
  // Dynamics also finds the static equilibrium first (2), but frees it before stepping.
  // One system-sized factorisation like HHT's: the one-step types and the multistep ones.
  if (in.type == "hht" || in.type == "central_difference" || in.type == "rattle" ||
      in.type == "petsc" || in.type == "bdf" || in.type == "park" || in.type == "abm")
    return 2.0;
  // Decoupled: a real block and complex ones (16-byte entries, more fill), measured on a
  // 200 000-element cable at twice HHT's per stage pair; coupled: the sn × sn system.
  const double s = in.stages;
  const bool coupled = in.linear_algebra == "coupled" || in.newton == "full" ||
                       in.type == "lobatto_iiia" || in.type == "sdirk";
  return std::max(2.0 * s, coupled ? s * s : 0.0);
}

MemoryEstimate estimate_memory(const ProblemSize& size) {
  MemoryEstimate e;
  e.size = size;
  const auto nodes = static_cast<double>(size.nodes);
  const auto elements = static_cast<double>(size.elements);
  const auto dofs = static_cast<double>(size.dofs);
  const auto nonzeros = static_cast<double>(size.matrix_nonzeros);
  e.model_bytes = nodes * (sizeof(Node) + kReaderBytesPerNode) +
                  elements * (sizeof(ElementDesc) + kReaderBytesPerElement);
  e.solver_bytes = elements * kAssemblyBytesPerElement + dofs * kVectorsPerDof * 8.0 +
                   nonzeros * kBytesPerNonzero * kMatricesPerFactor * size.factor_multiple;
  e.factor_bytes = nonzeros * kFactorFill * 8.0 * kMumpsOverhead * size.factor_multiple;
  e.output_bytes = 8.0 * (nodes * kOutputValuesPerNode + elements * kOutputValuesPerElement);
  return e;
}

double MemoryEstimate::per_host_bytes(int ranks, int ranks_on_host) const {
  const double shared = solver_bytes + factor_bytes + output_bytes;
  return ranks_on_host * (model_bytes + shared / std::max(ranks, 1));
}

std::string MemoryEstimate::describe(int ranks, int ranks_on_host) const {
  const double share = static_cast<double>(ranks_on_host) / std::max(ranks, 1);
  return format_gib(per_host_bytes(ranks, ranks_on_host)) + " (model " + format_gib(model_bytes) +
         " on each of " + std::to_string(ranks_on_host) +
         (ranks_on_host == 1 ? " rank" : " ranks") + ", matrices and vectors " +
         format_gib(solver_bytes * share) + ", LU factors " + format_gib(factor_bytes * share) +
         ", output " + format_gib(output_bytes * share) + "; " + std::to_string(size.dofs) +
         " DOFs, " + std::to_string(size.matrix_nonzeros) + " matrix non-zeros)";
}

double physical_memory_bytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES);
  const long page_size = ::sysconf(_SC_PAGESIZE);
  if (pages <= 0 || page_size <= 0) return 0.0;
  return static_cast<double>(pages) * static_cast<double>(page_size);
}

std::string format_gib(double bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g GiB", bytes / kGiB);
  return text;
}

std::string MemoryBudget::describe() const {
  const std::string ranks_text =
      std::to_string(ranks_on_host) + (ranks_on_host == 1 ? " rank" : " ranks") + " on it";
  const std::string whole =
      from_option ? "the --memory-limit per host" : "this host's physical memory";
  if (job_ranks_on_host > 0)
    return format_gib(host_bytes) + ", this run's share of " + whole + " (" + ranks_text +
           " of the job's " + std::to_string(job_ranks_on_host) + ")";
  if (from_option)
    return "the --memory-limit of " + format_gib(host_bytes) + " per host (" + ranks_text + ")";
  return "the " + format_gib(host_bytes) + " of physical memory of this host (" + ranks_text + ")";
}

}  // namespace catena::model
