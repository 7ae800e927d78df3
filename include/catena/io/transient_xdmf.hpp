#pragma once
// The XDMF descriptions of a dynamic run's time-series HDF5 file (docs/output.md, "Time
// series"), so that ParaView can play the run: a temporal collection with one polyline grid
// per sample, whose geometry and fields are selections of sample k of the /samples
// datasets (and, in scenes with rigid bodies, joints or sliders, a collection each: vertex
// grids at the bodies' and sliders' nodes, the joints' links as segments) — written in two
// flavours, one for each family of ParaView's XDMF readers (XdmfReaders). The XDMF only points into
// the HDF5 file, by its base name, so the files can be moved together.
//
// For the caller's rank 0, after the parallel HDF5 file is closed on every rank: these
// functions open it with serial HDF5 (the default file access property list).
//
//   if (rank == 0) {
//     const std::vector<double> times = catena::io::read_sample_times(path);
//     if (!times.empty())
//       catena::io::write_transient_xdmf(path, catena::io::transient_xdmf_path(path),
//                                        n_nodes, n_elements, times, XdmfReaders::xdmf3);
//   }
#include <cstdint>
#include <string>
#include <vector>

namespace catena::io {

// Which of ParaView's XDMF readers a description is for (checked with ParaView 5.11).
enum class XdmfReaders {
  // Xdmf3 Reader S/T, ParaView's default for .xmf: the sample selected inside each HDF
  // reference ("file:/dataset|start:stride:count:dimensions"); no computed fields, which
  // these readers drop.
  xdmf3,
  // The XDMF Reader, which ParaView picks for .xmf2: XDMF HyperSlab items, and the
  // displacements from the mesh and from the static equilibrium as Function items.
  xdmf2,
};

// Not collective. `hdf5_path` with its extension replaced by ".xmf" (appended if none), the
// same rule as for static results.
std::string transient_xdmf_path(const std::string& hdf5_path);

// Not collective. `hdf5_path` with its extension replaced by ".xmf2": the description for
// ParaView's XDMF Reader beside the .xmf.
std::string transient_xdmf2_path(const std::string& hdf5_path);

// Not collective. The sample times /time [s] of a closed time-series file.
// Throws catena::Error naming the file and the failing HDF5 call, or catena::InputError
// naming the file if its root attribute `format` is not "catena-transient-1" (the format
// found and the one expected).
std::vector<double> read_sample_times(const std::string& hdf5_path);

// Not collective. Writes `xdmf_path` atomically (a temporary sibling renamed into place, so
// an existing file is replaced only by a complete one) describing the closed time-series
// file `hdf5_path`: one grid per entry of `times` (the values of /time, in order; at least
// one: a file without samples gets no XDMF, and the call throws).
// `xdmf_path` must be in the same directory as `hdf5_path` and differ from it. The
// datasets' shapes and types are checked against n_nodes, n_elements and times.size()
// first (and the file's format, as read_sample_times does), so the XDMF never selects
// outside them. Throws catena::Error naming the files.
void write_transient_xdmf(const std::string& hdf5_path, const std::string& xdmf_path,
                          std::int64_t n_nodes, std::int64_t n_elements,
                          const std::vector<double>& times, XdmfReaders readers);

}  // namespace catena::io
