// The modal basis file (catena/io/modal_basis.hpp): written like the modes file (rows moved
// to balanced blocks, one collective write per dataset, renamed into place), read by every
// rank opening the file on its own, reading its balanced block of each mode and sending the
// rows to their owners.
#include "catena/io/modal_basis.hpp"

#include <filesystem>
#include <optional>
#include <sstream>

#include "catena/core/error.hpp"
#include "catena/core/mpi_comm.hpp"
#include "catena/io/atomic_file.hpp"
#include "catena/io/output_error.hpp"
#include "collective_phase.hpp"
#include "hdf5_attributes.hpp"
#include "hdf5_error.hpp"
#include "hdf5_parallel_write.hpp"
#include "hdf5_reader.hpp"
#include "row_redistribution.hpp"

namespace catena::io {
namespace {

namespace fs = std::filesystem;

constexpr const char* kFormat = "catena-modal-basis-1";
constexpr const char* kFrequency = "/frequency";
constexpr const char* kShapes = "/shapes";

std::string shape_name(std::size_t mode) { return "/shapes/mode_" + std::to_string(mode + 1); }

void write_atomically(MPI_Comm comm, const fs::path& path, const model::Model& model,
                      const BasisRows& rows, double cutoff_hz, const std::vector<double>& frequency,
                      const std::vector<std::span<const double>>& shapes,
                      const std::string& code_version) {
  const bool root = mpi_rank(comm) == 0;
  CollectiveTemporary temporary(comm, path);
  const auto n_modes = static_cast<std::int64_t>(frequency.size());
  {
    ParallelHdf5File file =
        run_collective_phase(comm, [&] { return ParallelHdf5File(comm, temporary.path.string()); });
    const RowRedistribution blocks(comm, rows.n_rows, rows.owned, "BasisRows::owned");
    std::vector<double> root_frequency;
    if (root) root_frequency = frequency;
    write_block_dataset<double>(file, {kFrequency, n_modes, 1, "Hz"},
                                RowBlock{0, root ? n_modes : 0}, root_frequency);
    create_group(file, kShapes);
    for (std::size_t k = 0; k < shapes.size(); ++k) {
      const std::string name = shape_name(k);
      write_block_dataset<double>(file, {name.c_str(), rows.n_rows, 1, "1/sqrt(kg) per unknown"},
                                  blocks.block(), blocks.to_block(shapes[k], 1));
    }
    run_output_phase(comm, [&] {
      const AttributeTarget root_group{file.id(), file.path()};
      write_string_attribute(root_group, "format", kFormat);
      write_double_attribute(root_group, "cutoff_hz", cutoff_hz);
      write_int64_attribute(root_group, "n_modes", n_modes);
      write_int64_attribute(root_group, "n_rows", rows.n_rows);
      write_int64_attribute(root_group, "n_nodes", static_cast<std::int64_t>(model.nodes.size()));
      write_int64_attribute(root_group, "n_elements",
                            static_cast<std::int64_t>(model.elements.size()));
      write_string_attribute(root_group, "scene_file", model.source_file);
      write_string_attribute(root_group, "code_version", code_version);
    });
    run_collective_phase(comm, [&] { file.close(); });
  }
  publish_written_file(comm, temporary, path);
}

// This rank's reading: the file's facts checked against the model and the request, then
// its balanced block of each kept mode.
struct BlockRead {
  double cutoff_hz = 0.0;
  std::vector<double> frequency;
  std::vector<std::vector<double>> blocks;
};

BlockRead read_blocks(const std::string& path, const model::Model& model, const BasisRows& rows,
                      const RowBlock& block, double cutoff_hz) {
  if (!fs::is_regular_file(path)) throw Error("no such file");
  const Hdf5Reader r(path);
  if (!r.has_attribute("format") || r.text("format") != kFormat)
    throw Error("not a modal basis (format '" +
                (r.has_attribute("format") ? r.text("format") : std::string()) + "', expected '" +
                kFormat + "')");
  const auto expect = [&](const char* name, std::int64_t here) {
    const std::int64_t there = r.integer(name);
    if (there != here)
      throw Error(std::string(name) + " = " + std::to_string(there) + " in the file, " +
                  std::to_string(here) + " in this scene (another model)");
  };
  expect("n_nodes", static_cast<std::int64_t>(model.nodes.size()));
  expect("n_elements", static_cast<std::int64_t>(model.elements.size()));
  expect("n_rows", rows.n_rows);
  BlockRead out;
  out.cutoff_hz = r.real("cutoff_hz");
  if (out.cutoff_hz < cutoff_hz) {
    std::ostringstream why;
    why << "it holds the modes below " << out.cutoff_hz << " Hz, this run asks for " << cutoff_hz
        << " Hz (analysis.modal_cutoff)";
    throw Error(why.str());
  }
  const std::int64_t n_modes = r.integer("n_modes");
  const std::vector<double> all = r.values(kFrequency, static_cast<std::size_t>(n_modes));
  for (double f : all)
    if (f <= cutoff_hz) out.frequency.push_back(f);
  for (std::size_t k = 0; k < out.frequency.size(); ++k)
    out.blocks.push_back(r.rows(shape_name(k).c_str(), rows.n_rows, block.begin, block.count));
  return out;
}

}  // namespace

void write_modal_basis(MPI_Comm comm, const std::string& path, const model::Model& model,
                       const BasisRows& rows, double cutoff_hz,
                       const std::vector<double>& frequency,
                       const std::vector<std::span<const double>>& shapes,
                       const std::string& code_version) {
  CATENA_ASSERT(frequency.size() == shapes.size(), "a frequency per mode");
  write_result_file(path, [&] {
    write_atomically(comm, fs::path(path), model, rows, cutoff_hz, frequency, shapes, code_version);
  });
}

ModalBasis read_modal_basis(MPI_Comm comm, const std::string& path, const model::Model& model,
                            const BasisRows& rows, double cutoff_hz) {
  const Hdf5ErrorPrintingSuppressed quiet_hdf5;
  const RowRedistribution blocks(comm, rows.n_rows, rows.owned, "BasisRows::owned");
  try {
    const BlockRead read = run_collective_phase(
        comm, [&] { return read_blocks(path, model, rows, blocks.block(), cutoff_hz); });
    // Every rank read the file on its own: had it been replaced in between (another run
    // writing the same basis), the ranks would disagree on the modes, and on how many
    // exchanges follow.
    long kept[2] = {static_cast<long>(read.frequency.size()),
                    -static_cast<long>(read.frequency.size())};
    MPI_Allreduce(MPI_IN_PLACE, kept, 2, MPI_LONG, MPI_MAX, comm);
    if (kept[0] != -kept[1])
      throw Error(
          "the ranks read different numbers of modes from it (the file was replaced "
          "while it was read); run again");
    ModalBasis basis;
    basis.cutoff_hz = read.cutoff_hz;
    basis.frequency = read.frequency;
    for (const std::vector<double>& block : read.blocks)
      basis.shapes.push_back(blocks.from_block(block, 1));
    return basis;
  } catch (const InputError&) {
    throw;
  } catch (const Error& e) {
    throw InputError(InputLocation{path, 0, "analysis.modal_basis"},
                     std::string("cannot use this modal basis: ") + e.what());
  }
}

}  // namespace catena::io
