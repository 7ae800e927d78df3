// write_static_result: the static solution as one HDF5 file written by all ranks through
// MPI-IO, plus an XDMF file for ParaView. Layout, units and ordering: docs/output.md; the
// names: static_result_layout.hpp.
//
// The sequence, every step collective and followed by an agreement on failure
// (collective_phase.hpp), so that an error on one rank makes every rank throw, not hang:
//   1. check the result against the model, and the output path (rank 0);
//   2. plan the row moves: owner rows → balanced contiguous blocks (row_redistribution.hpp);
//   3. create "<path>.tmp-<pid of rank 0>" with the MPI-IO driver; write the mesh (from the
//      model, which every rank holds), the solution and the attributes; close;
//   4. fsync (once per node), write the XDMF to its own temporary name (rank 0);
//   5. rank 0 renames both into place and fsyncs the directory.
// Until 5 succeeds, the temporary files are removed on failure and `path` is untouched.
#include "catena/io/hdf5_writer.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/core/mpi_comm.hpp"
#include "catena/core/version.hpp"
#include "catena/io/atomic_file.hpp"
#include "catena/io/output_error.hpp"
#include "catenary_output.hpp"
#include "collective_phase.hpp"
#include "element_classes.hpp"
#include "hdf5_attributes.hpp"
#include "hdf5_error.hpp"
#include "hdf5_parallel_write.hpp"
#include "row_redistribution.hpp"
#include "static_result_checks.hpp"
#include "static_result_layout.hpp"
#include "xdmf_writer.hpp"

namespace catena::io {
namespace {

namespace layout = static_layout;
namespace fs = std::filesystem;

// Attribute values, identical on every rank: parallel HDF5 requires every rank to write
// the same metadata, so rank 0's values are broadcast rather than trusted to agree.
struct FileAttributes {
  std::string scene_text, scene_file, code_version, command_line, petsc_options;
  std::int64_t n_ranks = 0, n_dofs = 0, n_load_steps = 0, n_newton_iterations = 0;
  double load_factor = 0.0, residual_norm = 0.0;
};

// Collective.
FileAttributes broadcast_file_attributes(MPI_Comm comm, const model::Model& model,
                                         const StaticResult& result, const RunInfo& info) {
  FileAttributes attributes{
      .scene_text = model.source_text,
      .scene_file = model.source_file,
      // A file must always say which code wrote it: fall back on this build's version.
      .code_version = info.code_version.empty()
                          ? std::string(version()) + " (" + git_version() + ")"
                          : info.code_version,
      .command_line = info.command_line,
      .petsc_options = info.petsc_options,
      .n_ranks = info.n_ranks,
      .n_dofs = info.n_dofs,
      .n_load_steps = result.n_load_steps,
      .n_newton_iterations = result.n_newton_iterations,
      .load_factor = result.load_factor,
      .residual_norm = result.residual_norm,
  };
  for (std::string* text :
       {&attributes.scene_text, &attributes.scene_file, &attributes.code_version,
        &attributes.command_line, &attributes.petsc_options})
    broadcast_string(comm, *text);
  std::array<std::int64_t, 4> counts{attributes.n_ranks, attributes.n_dofs, attributes.n_load_steps,
                                     attributes.n_newton_iterations};
  std::array<double, 2> measures{attributes.load_factor, attributes.residual_norm};
  MPI_Bcast(counts.data(), static_cast<int>(counts.size()), MPI_INT64_T, 0, comm);
  MPI_Bcast(measures.data(), static_cast<int>(measures.size()), MPI_DOUBLE, 0, comm);
  attributes.n_ranks = counts[0];
  attributes.n_dofs = counts[1];
  attributes.n_load_steps = counts[2];
  attributes.n_newton_iterations = counts[3];
  attributes.load_factor = measures[0];
  attributes.residual_norm = measures[1];
  return attributes;
}

// Collective. Every rank's support nodes, in ascending node order: the row order of the
// support datasets. (Concatenating the ranks' lists, as an MPI_Exscan of counts would,
// gives an order that depends on the partition.) Supports are few; gathering them all is
// cheap.
std::vector<int> gather_support_nodes(MPI_Comm comm, const std::vector<int>& my_support_nodes) {
  const int n_ranks = mpi_size(comm);
  const int my_count = static_cast<int>(my_support_nodes.size());
  std::vector<int> counts(static_cast<std::size_t>(n_ranks)),
      offsets(static_cast<std::size_t>(n_ranks), 0);
  MPI_Allgather(&my_count, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  for (std::size_t r = 1; r < counts.size(); ++r) offsets[r] = offsets[r - 1] + counts[r - 1];
  std::vector<int> all_support_nodes(static_cast<std::size_t>(offsets.back() + counts.back()));
  MPI_Allgatherv(my_support_nodes.data(), my_count, MPI_INT, all_support_nodes.data(),
                 counts.data(), offsets.data(), MPI_INT, comm);
  std::sort(all_support_nodes.begin(), all_support_nodes.end());
  return all_support_nodes;
}

// Not collective. Where each of my support nodes sits in the ascending list of all.
std::vector<int> support_rows_of(const std::vector<int>& my_support_nodes,
                                 const std::vector<int>& all_support_nodes) {
  std::vector<int> rows;
  rows.reserve(my_support_nodes.size());
  for (const int node : my_support_nodes)
    rows.push_back(static_cast<int>(
        std::lower_bound(all_support_nodes.begin(), all_support_nodes.end(), node) -
        all_support_nodes.begin()));
  return rows;
}

std::size_t row_index(const RowBlock& block, std::int64_t k) {
  return static_cast<std::size_t>(block.begin + k);
}

// Everything the dataset writers need, bundled to keep their parameter lists short.
struct WriteContext {
  MPI_Comm comm;
  const ParallelHdf5File& file;
  const model::Model& model;
};

// Collective. One phase per dataset: build this rank's block, then create and write.
template <class Value, class BuildBlock>
void write_dataset_phase(const WriteContext& context, const BlockDataset& dataset,
                         const RowBlock& block, BuildBlock&& build_block) {
  run_collective_phase(context.comm, [&] {
    const std::vector<Value> block_values = build_block();
    write_block_dataset<Value>(context.file, dataset, block, block_values);
  });
}

// Collective. /mesh: every rank holds the whole model, so each writes its balanced block
// straight from it, with no communication.
void write_mesh(const WriteContext& context, const RowBlock& node_block,
                const RowBlock& element_block) {
  const model::Model& model = context.model;
  const auto n_nodes = static_cast<std::int64_t>(model.nodes.size());
  const auto n_elements = static_cast<std::int64_t>(model.elements.size());

  const auto node_ids = [&] {
    std::vector<std::int64_t> ids;
    for (std::int64_t k = 0; k < node_block.count; ++k)
      ids.push_back(model.nodes[row_index(node_block, k)].id);
    return ids;
  };
  write_dataset_phase<std::int64_t>(context, {layout::node_ids, n_nodes, 1}, node_block, node_ids);
  const auto reference_positions = [&] {
    std::vector<double> positions;
    for (std::int64_t k = 0; k < node_block.count; ++k) {
      const Vec3& x = model.nodes[row_index(node_block, k)].position;
      positions.insert(positions.end(), {x.x(), x.y(), x.z()});
    }
    return positions;
  };
  write_dataset_phase<double>(context, {layout::node_positions, n_nodes, 3, "m"}, node_block,
                              reference_positions);
  write_dataset_phase<std::int64_t>(
      context, {layout::element_ids, n_elements, 1}, element_block, [&] {
        std::vector<std::int64_t> ids;
        for (std::int64_t k = 0; k < element_block.count; ++k)
          ids.push_back(model.elements[row_index(element_block, k)].id);
        return ids;
      });
  write_dataset_phase<std::int64_t>(
      context, {layout::element_nodes, n_elements, layout::nodes_per_element}, element_block, [&] {
        std::vector<std::int64_t> nodes;
        for (std::int64_t k = 0; k < element_block.count; ++k)
          for (const int node : model.elements[row_index(element_block, k)].nodes)
            nodes.push_back(node);
        return nodes;
      });

  run_collective_phase(context.comm,
                       [&] { write_element_classes(context.file, model, element_block); });
}

// How the rows of the solution move from their owners to their writers.
struct SolutionRows {
  RowRedistribution nodes, elements, supports;
  std::vector<int> all_support_nodes;  // ascending: row k of the support datasets
};

// Collective. Nodes first: their check of disjoint ownership also vouches for the
// supports, which are owned nodes.
SolutionRows plan_solution_rows(MPI_Comm comm, const model::Model& model,
                                const StaticResult& result) {
  RowRedistribution nodes(comm, static_cast<std::int64_t>(model.nodes.size()), result.owned_nodes,
                          "StaticResult::owned_nodes");
  RowRedistribution elements(comm, static_cast<std::int64_t>(model.elements.size()),
                             result.owned_elements, "StaticResult::owned_elements");
  std::vector<int> all_support_nodes = gather_support_nodes(comm, result.support_nodes);
  RowRedistribution supports(comm, static_cast<std::int64_t>(all_support_nodes.size()),
                             support_rows_of(result.support_nodes, all_support_nodes),
                             "StaticResult::support_nodes");
  return {std::move(nodes), std::move(elements), std::move(supports), std::move(all_support_nodes)};
}

// Collective. /static: owner rows are moved to blocks (one MPI_Alltoallv per dataset)
// and written.
void write_solution(const WriteContext& context, const StaticResult& result,
                    const SolutionRows& rows) {
  const model::Model& model = context.model;
  const auto n_nodes = static_cast<std::int64_t>(model.nodes.size());
  const auto n_elements = static_cast<std::int64_t>(model.elements.size());
  const auto n_supports = static_cast<std::int64_t>(rows.all_support_nodes.size());
  const RowBlock& node_block = rows.nodes.block();
  const RowBlock& element_block = rows.elements.block();
  const RowBlock& support_block = rows.supports.block();

  // The block's positions serve twice: written, then turned into displacements.
  std::vector<double> positions;
  write_dataset_phase<double>(context, {layout::positions, n_nodes, 3, "m"}, node_block, [&] {
    positions = rows.nodes.to_block(result.positions, 3);
    return positions;
  });
  write_dataset_phase<double>(context, {layout::slopes, n_nodes, 3, "1"}, node_block,
                              [&] { return rows.nodes.to_block(result.slopes, 3); });
  const auto displacements = [&] {
    std::vector<double> block_displacements = positions;
    for (std::int64_t k = 0; k < node_block.count; ++k) {
      const Vec3& reference = model.nodes[row_index(node_block, k)].position;
      for (int i = 0; i < 3; ++i)
        block_displacements[static_cast<std::size_t>(3 * k + i)] -= reference[i];
    }
    return block_displacements;
  };
  write_dataset_phase<double>(context, {layout::displacements, n_nodes, 3, "m"}, node_block,
                              displacements);

  write_dataset_phase<double>(context, {layout::axial_force, n_elements, 1, "N"}, element_block,
                              [&] { return rows.elements.to_block(result.axial_force, 1); });
  write_dataset_phase<double>(context, {layout::axial_strain, n_elements, 1, "1"}, element_block,
                              [&] { return rows.elements.to_block(result.axial_strain, 1); });
  write_dataset_phase<double>(context, {layout::shear_force, n_elements, 3, "N"}, element_block,
                              [&] { return rows.elements.to_block(result.shear_force, 3); });
  write_dataset_phase<double>(context, {layout::bending_moment, n_elements, 3, "N m"},
                              element_block,
                              [&] { return rows.elements.to_block(result.bending_moment, 3); });
  write_dataset_phase<double>(context, {layout::torsion, n_elements, 1, "N m"}, element_block,
                              [&] { return rows.elements.to_block(result.torsion, 1); });

  write_dataset_phase<std::int64_t>(
      context, {layout::support_nodes, n_supports, 1}, support_block, [&] {
        const auto first = rows.all_support_nodes.begin() + support_block.begin;
        return std::vector<std::int64_t>(first, first + support_block.count);
      });
  write_dataset_phase<double>(context, {layout::reaction_force, n_supports, 3, "N"}, support_block,
                              [&] { return rows.supports.to_block(result.reaction_force, 3); });
  write_dataset_phase<double>(context, {layout::reaction_moment, n_supports, 3, "N m"},
                              support_block,
                              [&] { return rows.supports.to_block(result.reaction_moment, 3); });
}

// Collective.
void write_attributes(const ParallelHdf5File& file, const FileAttributes& attributes) {
  const AttributeTarget root{file.id(), file.path()};
  write_string_attribute(root, "format", layout::format);
  write_string_attribute(root, "units", layout::units);
  write_string_attribute(root, "scene_text", attributes.scene_text);
  write_string_attribute(root, "scene_file", attributes.scene_file);
  write_string_attribute(root, "code_version", attributes.code_version);
  write_string_attribute(root, "command_line", attributes.command_line);
  write_string_attribute(root, "petsc_options", attributes.petsc_options);
  write_int64_attribute(root, "n_ranks", attributes.n_ranks);
  write_int64_attribute(root, "n_dofs", attributes.n_dofs);

  const GroupHandle solution(checked_hdf5_id(H5Gopen2(file.id(), layout::static_group, H5P_DEFAULT),
                                             "H5Gopen2", file.path(), layout::static_group));
  const AttributeTarget static_group{solution.get(), file.path()};
  write_double_attribute(static_group, "load_factor", attributes.load_factor);
  write_int64_attribute(static_group, "n_load_steps", attributes.n_load_steps);
  write_int64_attribute(static_group, "n_newton_iterations", attributes.n_newton_iterations);
  write_double_attribute(static_group, "residual_norm", attributes.residual_norm);
}

// Collective. Steps 1–5 of the file comment.
void write_atomically(MPI_Comm comm, const fs::path& path, const model::Model& model,
                      const StaticResult& result, const RunInfo& info) {
  CATENA_ASSERT(info.n_ranks == mpi_size(comm), "RunInfo::n_ranks is the communicator's size");
  const bool is_root = mpi_rank(comm) == 0;
  const fs::path xdmf_path = xdmf_path_for(path);

  run_collective_phase(comm, [&] {
    check_result_matches_model(model, result);
    if (is_root) check_output_paths(path, xdmf_path);
  });

  const SolutionRows rows = plan_solution_rows(comm, model, result);
  const FileAttributes attributes = broadcast_file_attributes(comm, model, result, info);

  CollectiveTemporary hdf5_temporary(comm, path), xdmf_temporary(comm, xdmf_path);

  {
    ParallelHdf5File file = run_collective_phase(
        comm, [&] { return ParallelHdf5File(comm, hdf5_temporary.path.string()); });
    run_collective_phase(comm, [&] {
      create_group(file, layout::mesh_group);
      create_group(file, layout::static_group);
    });
    const WriteContext context{comm, file, model};
    write_mesh(context, rows.nodes.block(), rows.elements.block());
    write_solution(context, result, rows);
    run_collective_phase(comm, [&] { write_catenary_layout(file, model); });
    run_collective_phase(comm, [&] { write_attributes(file, attributes); });
    run_collective_phase(comm, [&] { file.close(); });
  }
  fsync_once_per_node(comm, hdf5_temporary.path);

  run_collective_phase(comm, [&] {
    if (!is_root) return;
    const XdmfStaticGrid grid{path.filename().string(),
                              static_cast<std::int64_t>(model.nodes.size()),
                              static_cast<std::int64_t>(model.elements.size())};
    write_file_durably(xdmf_temporary.path, static_result_xdmf(grid));
  });
  run_collective_phase(comm, [&] {
    if (!is_root) return;
    publish_with_xdmf(*hdf5_temporary.owner, path, *xdmf_temporary.owner, xdmf_path);
  });
}

}  // namespace

void write_static_result(MPI_Comm comm, const std::string& path, const model::Model& model,
                         const StaticResult& result, const RunInfo& info) {
  write_result_file(path, [&] { write_atomically(comm, fs::path(path), model, result, info); });
}

}  // namespace catena::io
