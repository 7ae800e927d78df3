#pragma once
// Time-series HDF5 output of a dynamic run, written in parallel (collective MPI-IO) while
// the run goes on. Layout (docs/output.md): /mesh (node ids, reference positions, element
// nodes), /time, /samples/{positions, velocities, slopes} (n_samples × n_nodes × 3),
// /samples/axial_force (n_samples × n_elements), with constraints /mesh/constraint_nodes
// (n_constraints × 2 node indices, −1: none) and /samples/constraint_forces
// (n_samples × n_constraints × model::multiplier_width: −λ, for a node constraint the force
// on node A), with supports /mesh/support_nodes
// and /samples/reaction_force, /samples/reaction_moment (n_samples × n_supports × 3),
// /steps/* (one row per accepted
// step), with pantographs /samples/contact_force and /samples/contact_position
// (n_samples × n_pantographs), /steps/contact_force (n_steps × n_pantographs), a group
// /pantographs/<name> each (attributes index, speed), with rigid bodies /mesh/body_nodes,
// /samples/body_orientation (n_samples × n_bodies × 4, quaternions) and
// /samples/body_angular_velocity (× 3) and a group /bodies/<name> each (attribute index),
// with joints /samples/joint_links (n_samples × n_joints × 4 × 3, the mechanism's links),
// with sliders /samples/slider_position and /samples/slider_speed (n_samples × n_sliders)
// and a group /sliders/<name> each (attribute index), /mesh/slider_nodes,
// /mesh/registration_nodes and root
// attributes evaluation_start/end, and root attributes (`format` = "catena-transient-1",
// `scene_text`, run facts, `status`). Every name is defined once, in
// src/io/transient_layout.hpp.
//
// The file is written in place (not atomically) so that a long run's results up to the
// last flush() are readable after a crash: flush() writes the buffered sample and step rows and
// H5Fflush()es, so a reader sees a consistent file up to that point. close() records
// `status` ("complete", "interrupted" or "failed: <why>") and the run statistics. A file
// whose `status` is still "running" ended without close(): data up to the last flush.
//
// Write failures (disk full, quota, I/O error — even on one rank only) are agreed between
// the ranks: every collective call throws the same catena::OutputError on every rank
// together, never leaving a rank behind in a collective call. After a failure the file is
// not written again; close() records the status and closes the file if a test write beside
// it succeeds, else it abandons the file (hdf5_parallel_write.hpp: closing it would write
// its last metadata, which can hang HDF5 1.10 when that fails on some ranks only).
#include <mpi.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "catena/io/static_result.hpp"
#include "catena/model/model.hpp"

namespace catena::io {

struct StepRecord {
  double time = 0.0, dt = 0.0;
  int newton_iterations = 0;
  double error = -1.0;
  int rejected = 0;
  std::vector<double> contact_force;  // N, one per model::MovingContact, at the step end
  // m, z of each model::Model::registration_nodes entry (in order) at the step end.
  std::vector<double> registration_height;
  std::int64_t window_moves = 0;  // catenary.window: how often it had moved by the step's end
};

// Reactions at a sample: 3 values each per owned supported node, ascending (the order of
// assembly::StateView::reactions).
struct SupportSample {
  std::vector<double> force;   // N
  std::vector<double> moment;  // N·m
};

// Contact state of every pantograph at a sample (identical on every rank).
struct ContactSample {
  std::vector<double> force;      // N
  std::vector<double> position;   // m along the path (with catenary.window: the line's)
  std::int64_t window_moves = 0;  // catenary.window: how often it had moved by the sample
};

// Every rigid body's pose at a sample (identical on every rank; assembly::BodyPoses).
struct BodySample {
  std::vector<double> orientation;       // 4 per body: unit quaternion (w, x, y, z)
  std::vector<double> angular_velocity;  // rad/s, 3 per body
  std::vector<double> joint_links;       // m, 12 per joint (assembly::StateView::joint_links)
};

// Every slider's travel at a sample (identical on every rank; assembly::SliderTravel).
struct SliderSample {
  std::vector<double> position;  // m along its path, 1 per slider
  std::vector<double> speed;     // m/s, 1 per slider
};

// Where a restarted run continues an existing output file: the rows it had when the
// checkpoint was taken (later rows, written before the run stopped, are cut off).
struct ResumePoint {
  std::int64_t samples = 0;
  std::int64_t steps = 0;
};

class TransientWriter {
 public:
  // Collective. Creates `path` (truncating it) and writes the mesh and run facts.
  // owned_nodes/owned_elements/owned_constraints: this rank's rows, ascending; every
  // node/element/constraint is owned by exactly one rank.
  TransientWriter(MPI_Comm comm, const std::string& path, const model::Model& model,
                  const RunInfo& info, std::vector<int> owned_nodes,
                  std::vector<int> owned_elements, std::vector<int> owned_constraints = {});
  // Collective. Reopens `path`, written by an earlier run of the same model, and continues
  // it at `resume` (status back to "running"). Throws catena::Error naming the file if it
  // does not have the layout above (another `format`, or none: the format found and the
  // one expected), or fewer rows than `resume`.
  TransientWriter(MPI_Comm comm, const std::string& path, const model::Model& model,
                  std::vector<int> owned_nodes, std::vector<int> owned_elements,
                  std::vector<int> owned_constraints, const ResumePoint& resume);
  ~TransientWriter();

  // Rows written so far, those buffered until flush() included.
  std::int64_t samples_written() const;
  std::int64_t steps_written() const;
  TransientWriter(const TransientWriter&) = delete;
  TransientWriter& operator=(const TransientWriter&) = delete;

  // Collective. One sample: this rank's owned rows (3 values per node, 1 per element, 3
  // per constraint, 3 + 3 per supported node among its owned nodes). Buffered: written
  // 32 samples at a time, and by flush().
  void append_sample(double t, const std::vector<double>& positions,
                     const std::vector<double>& velocities, const std::vector<double>& slopes,
                     const std::vector<double>& axial_force,
                     const std::vector<double>& constraint_forces = {},
                     const ContactSample& contacts = {}, const SupportSample& supports = {},
                     const BodySample& bodies = {}, const SliderSample& sliders = {});
  // Not collective (identical on every rank): buffered until flush().
  void append_step(const StepRecord& record);
  // Collective. Writes buffered rows and flushes the file.
  void flush();
  // Collective. Flushes (unless a write failed before), records status and statistics,
  // closes the file; each step is attempted even if the one before failed (a failed flush
  // makes the status "failed: <why>"), but after a failed write only if a test write beside
  // the file succeeds: else the file is left unclosed. Throws the first catena::OutputError
  // (or says that the file is left unclosed), on every rank.
  void close(const std::string& status,
             const std::vector<std::pair<std::string, double>>& statistics);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace catena::io
