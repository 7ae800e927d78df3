#pragma once
// A new HDF5 file open on every rank through the MPI-IO driver, and collective writes of
// datasets whose rows are distributed over the ranks in contiguous blocks (see
// row_redistribution.hpp for how owner rows become blocks).
//
// Every collective call that can fail on some ranks only (creating or opening the file,
// creating a group or dataset, writing, flushing, closing) agrees on its outcome before
// anyone goes on (collective_hdf5_call.hpp): a failure throws catena::OutputError on every
// rank together, and the file is failed from then on.
//
// A failed file is abandoned, not closed: on a full disk, closing it would have to write
// its last metadata, and HDF5 1.10's parallel metadata flush, when it fails on some ranks
// only, leaves them in different collective calls (a hang), and even a close that fails
// on every rank leaves an id that crashes HDF5 when it shuts down. Abandoned, the file
// stays open until the process ends (the app keeps HDF5 from shutting down:
// catena/io/hdf5_library.hpp); on disk it holds what was written up to its last flush.
#include <hdf5.h>
#include <mpi.h>

#include <cstdint>
#include <span>
#include <string>
#include <utility>

#include "catena/io/output_error.hpp"
#include "collective_hdf5_call.hpp"
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
  // Collective. Closes the file silently, or abandons it if it failed.
  ~ParallelHdf5File();
  ParallelHdf5File(ParallelHdf5File&&) = default;
  ParallelHdf5File& operator=(ParallelHdf5File&&) = default;

  hid_t id() const { return file_.get(); }
  MPI_Comm comm() const { return comm_; }
  const std::string& path() const { return path_; }
  // Transfer property list for every H5Dwrite: collective MPI-IO.
  hid_t collective_transfer() const { return collective_transfer_.get(); }

  // Collective. Runs the collective HDF5 call `call` on this file, agreed between the
  // ranks (agreed_hdf5_call); a failure fails the file. Returns what `call` returned.
  template <class Call>
  auto agreed(const Hdf5CallSite& site, Call&& call) const {
    try {
      return agreed_hdf5_call(comm_, site, std::forward<Call>(call));
    } catch (const OutputError&) {
      failed_ = true;
      throw;
    }
  }
  // Collective. The same for a call that creates an object (agreed_hdf5_create).
  template <class Handle, class Create>
  Handle agreed_create(const Hdf5CallSite& site, Create&& create) const {
    try {
      return agreed_hdf5_create<Handle>(comm_, site, std::forward<Create>(create));
    } catch (const OutputError&) {
      failed_ = true;
      throw;
    }
  }
  // Whether a write to the file failed (on any rank: the same on every rank).
  bool failed() const { return failed_; }

  // Not collective (every rank does it alike). Forgets the file without closing it (see
  // the file comment); objects still open in it must be forgotten too (release()).
  void abandon();

  // Collective. Writes the buffered metadata and data to the file (H5Fflush).
  void flush();

  // Collective. Closes the file, writing the remaining metadata; throws on failure. All
  // objects opened in the file must be closed before. The destructor closes silently.
  // Never retried: HDF5 1.10 releases the file even when its close fails (e.g. on a full
  // disk) but keeps its id, which must not be used again.
  void close();

 private:
  MPI_Comm comm_;
  std::string path_;
  mutable bool failed_ = false;
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
