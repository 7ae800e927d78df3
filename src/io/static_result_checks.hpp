#pragma once
// Checks made before a static result is written, so that a malformed result or an
// impossible output path fails up front, on every rank, before any file exists.
#include <filesystem>

#include "catena/io/static_result.hpp"
#include "catena/model/model.hpp"

namespace catena::io {

// Not collective. Throws catena::Error unless this rank's share of `result` fits `model`:
// owned lists strictly ascending and in range, one row of values per owned row, support
// nodes among the owned nodes, and every element a 2-node element with valid node indices.
// (That ownership is disjoint and complete over the ranks is checked when rows move to
// their writers, see row_redistribution.hpp.)
void check_result_matches_model(const model::Model& model, const StaticResult& result);

// Not collective (rank 0 calls it). Throws catena::Error unless the HDF5 file and its
// XDMF companion can be written: distinct names, an existing directory, and no directory
// already standing at either name (rename(2) could not replace it at the very end).
void check_output_paths(const std::filesystem::path& hdf5_path,
                        const std::filesystem::path& xdmf_path);

}  // namespace catena::io
