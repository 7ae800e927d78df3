#pragma once
// A new HDF5 file open on every rank through the MPI-IO driver, and collective writes of
// datasets whose rows are distributed over the ranks in contiguous blocks (see
// row_redistribution.hpp for how owner rows become blocks).
#include <hdf5.h>
#include <mpi.h>

#include <cstdint>
#include <span>
#include <string>

#include "hdf5_handles.hpp"
#include "row_redistribution.hpp"

namespace catena::io {

class ParallelHdf5File {
 public:
  // Collective. Creates `path` (truncating an existing file) for parallel writing.
  ParallelHdf5File(MPI_Comm comm, std::string path);
  // Collective. Opens the existing file `path` for parallel reading and writing (a
  // restarted run appending to its output).
  struct OpenExisting {};
  ParallelHdf5File(MPI_Comm comm, std::string path, OpenExisting);

  hid_t id() const { return file_.get(); }
  const std::string& path() const { return path_; }
  // Transfer property list for every H5Dwrite: collective MPI-IO.
  hid_t collective_transfer() const { return collective_transfer_.get(); }

  // Collective. Closes the file, writing the remaining metadata; throws on failure. All
  // objects opened in the file must be closed before. The destructor closes silently.
  void close();

 private:
  std::string path_;
  PropertyListHandle collective_transfer_;
  FileHandle file_;
};

// Collective. Creates the group `name` (absolute path, e.g. "/mesh").
GroupHandle create_group(const ParallelHdf5File& file, const char* name);

// Shape and meaning of a dataset written in row blocks.
struct BlockDataset {
  const char* name = "";       // absolute path, e.g. "/static/positions"
  std::int64_t n_rows = 0;     // global
  int n_columns = 1;           // 1: a 1-D dataset of n_rows; else n_rows × n_columns
  const char* unit = nullptr;  // stored as the "unit" attribute; nullptr: no attribute
};

// Collective. Creates `dataset` on every rank and writes this rank's `block` of rows with
// collective MPI-IO (a rank with an empty block selects nothing but still takes part).
// `block_values` holds n_columns values per row of the block, row-major. Instantiated for
// double, std::int64_t, std::int32_t and std::int8_t, stored little-endian.
template <class Value>
DatasetHandle write_block_dataset(const ParallelHdf5File& file, const BlockDataset& dataset,
                                  const RowBlock& block, std::span<const Value> block_values);

}  // namespace catena::io
