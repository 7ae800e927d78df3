#pragma once
// A rough estimate of the memory a run needs, from the model's size alone, so that a scene
// too large for the machine is refused with numbers before anything big is allocated
// (rather than dying of std::bad_alloc, or thrashing, part-way through). Every term is
// linear in a count: the model itself (every rank holds all of it), the solver's vectors,
// its sparse matrices and their LU factors, and the output rows. The factors dominate.
// Their size is estimated from the matrix's non-zeros: Catena's structures are chains of
// two-node elements (wires joined by droppers), banded under a good ordering, so that the
// factors fill in little beyond the band. The coefficients are measured peaks of
// `catena run` (docs/scene.md, "Memory"); the estimate is meant to be right within a factor
// of two, which is enough to refuse 10⁷ elements on a 24 GiB host and accept 10⁵.
// Measured on 200 000 cable elements (1.2e6 DOFs, one rank): statics 1.7 GiB (estimate
// 2.5), HHT 2.2 GiB (2.5), Radau IIA 3 stages over 6.9 GiB (6.4).
//
// Nothing here communicates: the app supplies the rank counts.
#include <cstdint>
#include <string>

#include "catena/model/model.hpp"

namespace catena::model {

// What the estimate is made of.
struct ProblemSize {
  std::int64_t nodes = 0;
  std::int64_t elements = 0;
  std::int64_t dofs = 0;             // nodal DOFs (supports not subtracted) + multipliers
  std::int64_t matrix_nonzeros = 0;  // of one n × n Newton matrix
  // The integrator's linear algebra, in multiples of one real n × n matrix and factor:
  // statics (tangent and its stability LDLᵀ) and HHT 2, an s-stage IRK 2s (decoupled:
  // its real and complex blocks) or max(2s, s²) (coupled, the sn × sn stage system).
  double factor_multiple = 1.0;
};

struct MemoryEstimate {
  ProblemSize size;
  double model_bytes = 0.0;   // per rank: the Model, held whole by every rank
  double solver_bytes = 0.0;  // the whole job: vectors and matrices
  double factor_bytes = 0.0;  // the whole job: LU factors
  double output_bytes = 0.0;  // the whole job: a sample's rows and the mesh tables
  // One host's share: each of its ranks holds the model and 1/ranks of the rest.
  double per_host_bytes(int ranks, int ranks_on_host) const;
  // "12.3 GiB (model 2.1 GiB per rank, matrices and vectors 1.2 GiB, LU factors 8.5 GiB,
  // output 0.1 GiB)" for `ranks` ranks, `ranks_on_host` of them on the fullest host.
  std::string describe(int ranks, int ranks_on_host) const;
};

// Not collective. The size of a model that has been read.
ProblemSize problem_size(const Model& model);

// Not collective. The estimate for `size` (whose factor_multiple the caller sets, or
// integrator_factor_multiple does).
MemoryEstimate estimate_memory(const ProblemSize& size);

// Not collective. ProblemSize::factor_multiple for the model's analysis and integrator.
double integrator_factor_multiple(const Model& model);

// Not collective. This host's physical memory, bytes (sysconf); 0 if unknown.
double physical_memory_bytes();

// "12.3 GiB".
std::string format_gib(double bytes);

// How much memory a run may use, and on how many ranks it runs. Set by the app; a
// budget with host_bytes = 0 checks nothing.
struct MemoryBudget {
  double host_bytes = 0.0;   // per host: physical memory, or --memory-limit
  bool from_option = false;  // host_bytes is the user's --memory-limit
  int ranks = 1;
  int ranks_on_host = 1;  // the most ranks any host runs
  // Concurrent runs of one job share a host (a study's groups, the comparison runs of
  // `catena run --error-bar-ranks`): host_bytes is then this run's share, its ranks' part
  // of the job's ranks on the host, and the description says so.
  int job_ranks_on_host = 0;  // the job's ranks on the host of the smallest share; 0: unshared
  bool active() const { return host_bytes > 0.0; }
  // "the 23.4 GiB of physical memory of this host (1 rank on it)" or the option's.
  std::string describe() const;
};

}  // namespace catena::model
