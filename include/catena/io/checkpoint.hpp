#pragma once
// Checkpoints of a dynamic run: the integrator's state at an accepted step, enough to
// continue the run with `catena run SCENE --restart` after a crash, a SIGTERM or a queue
// time limit, on any number of ranks — bit for bit as the uninterrupted run on the same
// number of ranks, to the Newton tolerance on another.
//
// File `<output>.chk` (HDF5, docs/output.md), format "catena-checkpoint-2":
//   /q, /v, /a     n_nodes × 12 (model::kMaxBlockUnknowns): each node's unknowns in its
//                  kind's layout (model/unknown_kinds.hpp; [r, r_x, r_y, r_z] for ANCF
//                  nodes), fixed and absent components 0;
//   /lambda        n_constraints × model::multiplier_width, the multipliers (rows padded);
//   attributes     time, last_dt, samples, steps (the output file's row counts at the
//                  checkpoint), integrator, ranks (of the run that wrote it), n_nodes,
//                  n_elements, n_constraints, format, and which run it belongs to:
//                  run_id (pairs it with its run's time series), code_version and
//                  scene_identity (model/scene_identity.hpp: a restart of another run
//                  is refused);
//   /resume        the step driver's and the integrator's step-to-step state
//                  (solvers/resume_state.hpp: the next step size, the point at which the
//                  reused tangent was evaluated, its age and freshness flags, the
//                  predictor's history, the counters): /resume/vectors/<name>
//                  (n_nodes × 12) and /resume/multipliers/<name> (n_constraints × multiplier_width)
//                  per vector, numbers as attributes of /resume (double or int64).
// Node-indexed rather than DOF-indexed, so it does not depend on the partition. Format 1
// (no /resume, no ranks) is still read: such a restart starts its Newton iteration afresh.
//
// Written atomically: a temporary sibling is written in parallel, fsynced, and renamed over
// the previous checkpoint by rank 0, so a crash during a checkpoint leaves the previous one.
#include <mpi.h>

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "catena/model/model.hpp"

namespace catena::io {

struct CheckpointFacts {
  double time = 0.0;     // s, the state's time
  double last_dt = 0.0;  // s, the last accepted step (an adaptive restart starts with it)
  std::int64_t samples = 0, steps = 0;  // output rows written up to the checkpoint
  std::string integrator;               // TimeIntegrator::name() of the run
  std::string run_id;                   // the run's identifier, also in its output file (run_id)
  std::string code_version;             // Catena version that wrote it
  int ranks = 0;                        // of the run that wrote it (0: not recorded)
};

// The solvers' step-to-step state (solvers/resume_state.hpp) in checkpoint form: each
// vector as node rows (12 per node) and multiplier rows (model::multiplier_width per constraint) —
// this rank's share in CheckpointShare, every node's in Checkpoint — and numbers identical on every
// rank.
struct ResumeRows {
  std::map<std::string, std::vector<double>> rows, multipliers;
  std::map<std::string, double> reals;
  std::map<std::string, std::int64_t> integers;
  bool empty() const { return rows.empty() && reals.empty() && integers.empty(); }
};

// This rank's share: owned nodes (ascending) with 12 values each of q, v, a, and owned
// constraints (ascending) with 3 multipliers each.
struct CheckpointShare {
  std::vector<int> nodes;
  std::vector<double> q, v, a;
  std::vector<int> constraints;
  std::vector<double> lambda;
  ResumeRows resume;  // rows of the same nodes and constraints
};

// Collective. Writes `path` atomically. On failure throws catena::OutputError on every
// rank ("cannot write the checkpoint '<path>': <why>"); the previous checkpoint is kept.
void write_checkpoint(MPI_Comm comm, const std::string& path, const model::Model& model,
                      const CheckpointFacts& facts, const CheckpointShare& share);

// The whole checkpoint (every node), as read back on every rank.
struct Checkpoint {
  CheckpointFacts facts;
  std::vector<double> q, v, a;  // 12 per node
  std::vector<double> lambda;   // model::multiplier_width per constraint
  ResumeRows resume;            // empty from a format-1 checkpoint
};

// Collective (every rank reads the file). Throws catena::InputError naming the file if it
// is missing or unreadable, and if it was written for a model with other node, element or
// constraint counts, by another integrator (`integrator`: this run's name) or by a run of
// another scene (model/scene_identity.hpp).
Checkpoint read_checkpoint(MPI_Comm comm, const std::string& path, const model::Model& model,
                           const std::string& integrator);

// Collective. Whether `path` is a readable checkpoint written for a model with other node,
// element or constraint counts (false if it is missing or unreadable).
bool checkpoint_of_another_model(MPI_Comm comm, const std::string& path, const model::Model& model);

}  // namespace catena::io
