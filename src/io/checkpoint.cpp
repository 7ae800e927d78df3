#include "catena/io/checkpoint.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>
#include <sstream>
#include <string>

#include "catena/core/error.hpp"
#include "catena/core/mpi_comm.hpp"
#include "catena/io/atomic_file.hpp"
#include "catena/io/output_error.hpp"
#include "catena/model/scene_identity.hpp"
#include "catena/model/unknown_kinds.hpp"
#include "collective_phase.hpp"
#include "hdf5_attributes.hpp"
#include "hdf5_error.hpp"
#include "hdf5_handles.hpp"
#include "hdf5_parallel_write.hpp"
#include "hdf5_reader.hpp"
#include "row_redistribution.hpp"

namespace catena::io {
namespace fs = std::filesystem;
namespace {

// 3: clamps hold a slope's direction only (model::Support::slope_direction), its rows the
// nodal values of a stretch unknown. 2: clamps fixed the whole slope, whose rows were 0.
// 1: no solver state (/resume).
constexpr const char* kFormat = "catena-checkpoint-3";
constexpr const char* kFormatWholeSlopeClamps = "catena-checkpoint-2";
constexpr const char* kFormatWithoutResume = "catena-checkpoint-1";

// The checkpoint's objects (checkpoint.hpp), written and read here only.
constexpr const char* kPositions = "/q";
constexpr const char* kVelocities = "/v";
constexpr const char* kAccelerations = "/a";
constexpr const char* kMultipliers = "/lambda";
constexpr const char* kResumeGroup = "/resume";
constexpr const char* kResumeVectors = "/resume/vectors";
constexpr const char* kResumeMultipliers = "/resume/multipliers";

// Row widths: a node's row holds the widest block of unknowns (model/unknown_kinds.hpp), so
// every node kind fits and the file does not depend on which kinds a scene uses.
constexpr std::size_t kNodeRow = model::kMaxBlockUnknowns;

// "<group>/<name>", a member of one of the /resume groups.
std::string member_path(const char* group, const std::string& name) {
  return std::string(group) + "/" + name;
}

bool known_format(const std::string& format) {
  return format == kFormat || format == kFormatWholeSlopeClamps || format == kFormatWithoutResume;
}

bool has_direction_clamps(const model::Model& model) {
  return std::any_of(model.supports.begin(), model.supports.end(),
                     [](const model::Support& s) { return s.slope_direction; });
}

std::int64_t count_of(const model::Model& m, const char* what) {
  const std::string w = what;
  if (w == "n_nodes") return static_cast<std::int64_t>(m.nodes.size());
  if (w == "n_elements") return static_cast<std::int64_t>(m.elements.size());
  return static_cast<std::int64_t>(m.constraints.size());
}

// Why the checkpoint open in r was written for another model than `model` (its node,
// element or constraint count differs), or "".
std::string other_model(const Hdf5Reader& r, const model::Model& model) {
  for (const char* count : {"n_nodes", "n_elements", "n_constraints"})
    if (r.integer(count) != count_of(model, count))
      return std::string(count) + " = " + std::to_string(r.integer(count)) +
             " in the checkpoint, " + std::to_string(count_of(model, count)) +
             " in this scene (a different model)";
  return {};
}

// Why the numbers read make no state to continue from (a damaged or hand-edited file), or
// "": a time, step or count that is not one, or a value of the state that is not a number.
std::string damaged_numbers(const Checkpoint& c) {
  const auto text = [](auto x) {
    std::ostringstream os;
    os << x;
    return os.str();
  };
  const CheckpointFacts& f = c.facts;
  if (!std::isfinite(f.time)) return "time = " + text(f.time) + " is not a finite number";
  if (!(std::isfinite(f.last_dt) && f.last_dt >= 0.0))
    return "last_dt = " + text(f.last_dt) + " is not a step (a finite number >= 0)";
  if (f.samples < 0 || f.steps < 0)
    return "samples = " + text(f.samples) + ", steps = " + text(f.steps) +
           " (counts of rows written, >= 0)";
  for (const auto& [name, values] : {std::pair{kPositions, &c.q},
                                     {kVelocities, &c.v},
                                     {kAccelerations, &c.a},
                                     {kMultipliers, &c.lambda}}) {
    const auto bad =
        std::find_if(values->begin(), values->end(), [](double x) { return !std::isfinite(x); });
    if (bad != values->end())
      return std::string(name) + " holds " + text(*bad) + " (value " + text(bad - values->begin()) +
             "), not a finite number";
  }
  return {};
}

// Reads the checkpoint on this rank; throws catena::Error saying why it cannot be used.
Checkpoint read_on_this_rank(const std::string& path, const model::Model& model,
                             const std::string& integrator) {
  auto fail = [&](const std::string& why) { throw Error(why); };
  if (!fs::is_regular_file(path))
    fail(
        "no such file (a run writes <output>.chk at its checkpoints, at SIGTERM/SIGINT "
        "and at the end)");
  const Hdf5Reader r(path);
  const std::string format = r.text("format");
  if (!known_format(format)) fail("not a Catena checkpoint (format " + format + ")");
  if (const std::string why = other_model(r, model); !why.empty()) fail(why);
  if (format != kFormat && has_direction_clamps(model))
    fail("written by an older Catena, whose clamps fixed the whole slope (format " + format +
         "); a clamp now holds the slope's direction and leaves its stretch free, so the "
         "state cannot be carried over; run afresh (without --restart)");
  if (!r.has_attribute("scene_identity"))
    fail(
        "written by an older Catena, which did not record which run it belongs to; run "
        "afresh (without --restart)");
  if (const std::string why = model::first_identity_difference(
          model::scene_identity(model.source_text), r.text("scene_identity"));
      !why.empty())
    fail("it belongs to another run (" + why +
         "; the scene after --set overrides must be "
         "the same, except analysis.duration and the output's file and wall-clock keys); run "
         "afresh (without --restart), which replaces it");
  Checkpoint c;
  c.facts.run_id = r.text("run_id");
  c.facts.code_version = r.text("code_version");
  c.facts.integrator = r.text("integrator");
  if (c.facts.integrator != integrator)
    fail("written by integrator " + c.facts.integrator + ", this run uses " + integrator);
  c.facts.time = r.real("time");
  c.facts.last_dt = r.real("last_dt");
  c.facts.samples = r.integer("samples");
  c.facts.steps = r.integer("steps");
  for (const char* name : {kPositions, kVelocities, kAccelerations, kMultipliers})
    if (!r.has(name)) fail("the file is damaged: it has no dataset " + std::string(name));
  const std::size_t n = model.nodes.size();
  c.q = r.values(kPositions, kNodeRow * n);
  c.v = r.values(kVelocities, kNodeRow * n);
  c.a = r.values(kAccelerations, kNodeRow * n);
  const auto multiplier_row = static_cast<std::size_t>(model::multiplier_width(model));
  c.lambda = r.values(kMultipliers, multiplier_row * model.constraints.size());
  if (const std::string why = damaged_numbers(c); !why.empty())
    fail("the file is damaged: " + why + "; run afresh (without --restart)");
  if (format == kFormatWithoutResume) return c;
  c.facts.ranks = static_cast<int>(r.integer("ranks"));
  r.numbers(kResumeGroup, c.resume.reals, c.resume.integers);
  for (const std::string& name : r.members(kResumeVectors)) {
    c.resume.rows[name] = r.values(member_path(kResumeVectors, name).c_str(), kNodeRow * n);
    c.resume.multipliers[name] = r.values(member_path(kResumeMultipliers, name).c_str(),
                                          multiplier_row * model.constraints.size());
  }
  return c;
}

// Collective. /resume: each vector's node and multiplier rows, the numbers as attributes
// (the maps iterate in the same order on every rank, as the collective creation needs).
void write_resume_rows(MPI_Comm comm, const ParallelHdf5File& file, const model::Model& model,
                       const RowRedistribution& nodes, const RowRedistribution& constraints,
                       const ResumeRows& resume) {
  const auto n_nodes = static_cast<std::int64_t>(model.nodes.size());
  const auto n_constraints = static_cast<std::int64_t>(model.constraints.size());
  const int multiplier_row = model::multiplier_width(model);
  const GroupHandle group = create_group(file, kResumeGroup);
  create_group(file, kResumeVectors);
  create_group(file, kResumeMultipliers);
  for (const auto& [name, rows] : resume.rows) {
    const std::string node_path = member_path(kResumeVectors, name);
    const std::vector<double> block = nodes.to_block(rows, kNodeRow);
    write_block_dataset<double>(file, {node_path.c_str(), n_nodes, kNodeRow}, nodes.block(), block);
    const std::string multiplier_path = member_path(kResumeMultipliers, name);
    const std::vector<double> lambda =
        constraints.to_block(resume.multipliers.at(name), multiplier_row);
    write_block_dataset<double>(file, {multiplier_path.c_str(), n_constraints, multiplier_row},
                                constraints.block(), lambda);
  }
  run_collective_phase(comm, [&] {
    const AttributeTarget target{group.get(), file.path()};
    for (const auto& [name, value] : resume.reals)
      write_double_attribute(target, name.c_str(), value);
    for (const auto& [name, value] : resume.integers)
      write_int64_attribute(target, name.c_str(), value);
  });
}

// Collective. write_checkpoint without the error's context.
void write_checkpoint_atomically(MPI_Comm comm, const std::string& path, const model::Model& model,
                                 const CheckpointFacts& facts, const CheckpointShare& share) {
  CollectiveTemporary temporary(comm, path);
  {
    ParallelHdf5File file =
        run_collective_phase(comm, [&] { return ParallelHdf5File(comm, temporary.path.string()); });
    const auto n_nodes = static_cast<std::int64_t>(model.nodes.size());
    const auto n_constraints = static_cast<std::int64_t>(model.constraints.size());
    const RowRedistribution nodes(comm, n_nodes, share.nodes, "checkpoint nodes");
    const RowRedistribution constraints(comm, n_constraints, share.constraints,
                                        "checkpoint constraints");
    for (auto [name, values] :
         {std::pair{kPositions, &share.q}, {kVelocities, &share.v}, {kAccelerations, &share.a}}) {
      const std::vector<double> block = nodes.to_block(*values, kNodeRow);
      write_block_dataset<double>(file, {name, n_nodes, kNodeRow}, nodes.block(), block);
    }
    const int multiplier_row = model::multiplier_width(model);
    const std::vector<double> lambda = constraints.to_block(share.lambda, multiplier_row);
    write_block_dataset<double>(file, {kMultipliers, n_constraints, multiplier_row, "N"},
                                constraints.block(), lambda);
    write_resume_rows(comm, file, model, nodes, constraints, share.resume);
    run_collective_phase(comm, [&] {
      const AttributeTarget root{file.id(), file.path()};
      write_string_attribute(root, "format", kFormat);
      write_int64_attribute(root, "ranks", mpi_size(comm));
      write_double_attribute(root, "time", facts.time);
      write_double_attribute(root, "last_dt", facts.last_dt);
      write_int64_attribute(root, "samples", facts.samples);
      write_int64_attribute(root, "steps", facts.steps);
      write_string_attribute(root, "integrator", facts.integrator);
      write_string_attribute(root, "run_id", facts.run_id);
      write_string_attribute(root, "code_version", facts.code_version);
      write_string_attribute(root, "scene_identity", model::scene_identity(model.source_text));
      for (const char* count : {"n_nodes", "n_elements", "n_constraints"})
        write_int64_attribute(root, count, count_of(model, count));
    });
    run_collective_phase(comm, [&] { file.close(); });
  }
  publish_written_file(comm, temporary, fs::path(path));
}

}  // namespace

void write_checkpoint(MPI_Comm comm, const std::string& path, const model::Model& model,
                      const CheckpointFacts& facts, const CheckpointShare& share) {
  const Hdf5ErrorPrintingSuppressed quiet_hdf5;
  try {
    write_checkpoint_atomically(comm, path, model, facts, share);
  } catch (const Error& agreed) {
    // Every failure above is agreed between the ranks (phases and agreed HDF5 calls).
    throw OutputError("cannot write the checkpoint '" + path + "': " + agreed.what());
  }
}

Checkpoint read_checkpoint(MPI_Comm comm, const std::string& path, const model::Model& model,
                           const std::string& integrator) {
  // Every rank reads; a failure on any rank becomes the same InputError on all of them.
  try {
    return run_collective_phase(comm, [&] { return read_on_this_rank(path, model, integrator); });
  } catch (const Error& e) {
    throw InputError(InputLocation{path, 0, ""},
                     std::string("cannot restart from this checkpoint: ") + e.what());
  }
}

bool checkpoint_of_another_model(MPI_Comm comm, const std::string& path,
                                 const model::Model& model) {
  try {
    return run_collective_phase(comm, [&] {
      if (!fs::is_regular_file(path)) return false;
      const Hdf5Reader r(path);
      return known_format(r.text("format")) && !other_model(r, model).empty();
    });
  } catch (const Error&) {
    return false;  // unreadable: read_checkpoint says why
  }
}

}  // namespace catena::io
