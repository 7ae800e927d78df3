#pragma once
// What `catena study` reads of a completed dynamic run besides its contact forces
// (contact_run_reader.hpp): the work it did (root attributes, docs/output.md "Time
// series") and the trajectory of a probe node. Serial HDF5, for one rank.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace catena::io {

// The run's work statistics (root attributes written when it ended).
struct RunWork {
  double t_reached = 0.0;     // s, simulated time reached
  double wall_seconds = 0.0;  // s, the dynamic run's wall time (initial state, model, stepping)
  // s, the time stepping and its output alone, from t_started to t_reached (a run continued
  // from a checkpoint: the part after the restart); files of an older Catena: wall_seconds
  // from 0.
  double stepping_seconds = 0.0;
  double t_started = 0.0;
  std::int64_t n_ranks = 0;
  std::int64_t n_dofs = 0;
  std::int64_t steps_accepted = 0;
  std::int64_t steps_rejected = 0;
  std::int64_t newton_iterations = 0;
  std::int64_t residual_evaluations = 0;
  std::int64_t factorizations = 0;
  std::int64_t linear_solves = 0;
  bool has_pantographs = false;  // the file has /samples/contact_force
};

// Not collective. Throws catena::InputError naming the file and the attribute when the file
// is not a complete Catena dynamic output of this format or lacks a work statistic.
RunWork read_run_work(const std::string& path);

// One node's positions at every sample.
struct NodeTrack {
  std::int64_t node_id = 0;                    // the scene's id
  std::array<double, 3> reference_position{};  // m, its mesh (reference) position
  std::vector<double> time;                    // s, /time
  std::vector<double> positions;               // m, n_samples × 3, row-major
};

// Not collective. The trajectory of the node with scene id `node_id`. Throws
// catena::InputError naming the file when it is not a complete dynamic output or has no
// such node (key "--probe", listing a few of the ids it has).
NodeTrack read_node_track(const std::string& path, std::int64_t node_id);

// Not collective. The scene id of the node whose reference position is within `tolerance`
// of `position` (the nearest): how a probe is found again in a run on another mesh, whose
// ids are numbered otherwise. Throws catena::InputError naming the file (key "--probe")
// when no node is that near (a mesh that does not nest the probe's point).
std::int64_t node_at(const std::string& path, const std::array<double, 3>& position,
                     double tolerance);

// Not collective. The scene id of the node that moves farthest from its first sampled
// position over the run (the first such node in file order on a tie): the study's probe
// when none is given. Reads /samples/positions a block of samples at a time.
std::int64_t most_displaced_node(const std::string& path);

}  // namespace catena::io
