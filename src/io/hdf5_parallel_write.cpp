#include "hdf5_parallel_write.hpp"

#include <array>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "catena/core/error.hpp"
#include "catena/core/mpi_comm.hpp"
#include "hdf5_attributes.hpp"
#include "hdf5_error.hpp"

namespace catena::io {
namespace {

// Memory type (this machine) and file type (fixed little-endian, so files compare equal
// across machines) of each value type written.
template <class Value>
struct Hdf5TypesOf;
template <>
struct Hdf5TypesOf<double> {
  static hid_t in_memory() { return H5T_NATIVE_DOUBLE; }
  static hid_t in_file() { return H5T_IEEE_F64LE; }
};
template <>
struct Hdf5TypesOf<std::int64_t> {
  static hid_t in_memory() { return H5T_NATIVE_INT64; }
  static hid_t in_file() { return H5T_STD_I64LE; }
};
template <>
struct Hdf5TypesOf<std::int32_t> {
  static hid_t in_memory() { return H5T_NATIVE_INT32; }
  static hid_t in_file() { return H5T_STD_I32LE; }
};
template <>
struct Hdf5TypesOf<std::int8_t> {
  static hid_t in_memory() { return H5T_NATIVE_INT8; }
  static hid_t in_file() { return H5T_STD_I8LE; }
};

PropertyListHandle create_property_list(hid_t property_class, const std::string& file_path) {
  return PropertyListHandle(checked_hdf5_id(H5Pcreate(property_class), "H5Pcreate", file_path));
}

// 1-D for a single column, so that scalar fields read as plain vectors.
DataspaceHandle rows_space(std::int64_t n_rows, int n_columns, const std::string& file_path,
                           const char* dataset_name) {
  const std::array<hsize_t, 2> dims{static_cast<hsize_t>(n_rows), static_cast<hsize_t>(n_columns)};
  const int rank = n_columns == 1 ? 1 : 2;
  return DataspaceHandle(checked_hdf5_id(H5Screate_simple(rank, dims.data(), nullptr),
                                         "H5Screate_simple", file_path, dataset_name));
}

// A testing hook (docs/output.md, "Testing hooks"): CATENA_HDF5_SYNC_BYTES=N sets the
// metadata cache's dirty-bytes threshold, at which parallel HDF5 makes every rank meet to
// write the metadata (a sync point), from its default of 256 KiB down to N (>= 512), so that
// tests meet sync points in every write instead of once in a long run.
// Collective: rank 0's value on every rank (HDF5 needs the same cache settings on all).
void apply_sync_bytes_hook(MPI_Comm comm, hid_t access, const std::string& path) {
  constexpr const char* variable = "CATENA_HDF5_SYNC_BYTES";
  std::string text;
  if (mpi_rank(comm) == 0)
    if (const char* value = std::getenv(variable); value != nullptr) text = value;
  broadcast_string(comm, text);
  if (text.empty()) return;
  char* end = nullptr;
  const long bytes = std::strtol(text.c_str(), &end, 10);
  if (*end != '\0' || bytes < 512 || bytes > (32L << 20))
    throw InputError({"", 0, variable}, std::string(variable) + "=" + text +
                                            ": accepted: a whole number of bytes, 512 to 33554432");
  H5AC_cache_config_t config{};
  config.version = H5AC__CURR_CACHE_CONFIG_VERSION;
  check_hdf5_status(H5Pget_mdc_config(access, &config), "H5Pget_mdc_config", path);
  config.dirty_bytes_threshold = static_cast<std::size_t>(bytes);
  check_hdf5_status(H5Pset_mdc_config(access, &config), "H5Pset_mdc_config", path);
}

}  // namespace

ParallelHdf5File::ParallelHdf5File(MPI_Comm comm, std::string path)
    : comm_(comm), path_(std::move(path)) {
  const PropertyListHandle access = create_property_list(H5P_FILE_ACCESS, path_);
  check_hdf5_status(H5Pset_fapl_mpio(access.get(), comm, MPI_INFO_NULL), "H5Pset_fapl_mpio", path_);
  apply_sync_bytes_hook(comm, access.get(), path_);
  // The 1.8 object format is the oldest with dense attribute storage (below).
  check_hdf5_status(H5Pset_libver_bounds(access.get(), H5F_LIBVER_V18, H5F_LIBVER_LATEST),
                    "H5Pset_libver_bounds", path_);
  const PropertyListHandle creation = create_property_list(H5P_FILE_CREATE, path_);
  // Root attributes in dense storage: compact attributes (the default) are limited to
  // 64 KiB in the object header, and the scene text stored there can be longer.
  check_hdf5_status(H5Pset_attr_phase_change(creation.get(), 0, 0), "H5Pset_attr_phase_change",
                    path_);
  file_ = agreed_create<FileHandle>({"H5Fcreate", path_}, [&] {
    return H5Fcreate(path_.c_str(), H5F_ACC_TRUNC, creation.get(), access.get());
  });
  collective_transfer_ = create_property_list(H5P_DATASET_XFER, path_);
  check_hdf5_status(H5Pset_dxpl_mpio(collective_transfer_.get(), H5FD_MPIO_COLLECTIVE),
                    "H5Pset_dxpl_mpio", path_);
}

ParallelHdf5File::ParallelHdf5File(MPI_Comm comm, std::string path, OpenExisting)
    : comm_(comm), path_(std::move(path)) {
  const PropertyListHandle access = create_property_list(H5P_FILE_ACCESS, path_);
  check_hdf5_status(H5Pset_fapl_mpio(access.get(), comm, MPI_INFO_NULL), "H5Pset_fapl_mpio", path_);
  apply_sync_bytes_hook(comm, access.get(), path_);
  file_ = agreed_create<FileHandle>(
      {"H5Fopen", path_}, [&] { return H5Fopen(path_.c_str(), H5F_ACC_RDWR, access.get()); });
  collective_transfer_ = create_property_list(H5P_DATASET_XFER, path_);
  check_hdf5_status(H5Pset_dxpl_mpio(collective_transfer_.get(), H5FD_MPIO_COLLECTIVE),
                    "H5Pset_dxpl_mpio", path_);
}

ParallelHdf5File::~ParallelHdf5File() {
  if (failed_) abandon();
}

void ParallelHdf5File::abandon() {
  (void)file_.release();
  (void)collective_transfer_.release();
}

void ParallelHdf5File::flush() {
  agreed({"H5Fflush", path_, "/"}, [&] { return H5Fflush(file_.get(), H5F_SCOPE_GLOBAL); });
}

void ParallelHdf5File::close() {
  // The handle forgets the id before the call: a failed close is not attempted again.
  agreed({"H5Fclose", path_}, [&] { return file_.close(); });
}

GroupHandle create_group(const ParallelHdf5File& file, const char* name) {
  return file.agreed_create<GroupHandle>({"H5Gcreate2", file.path(), name}, [&] {
    return H5Gcreate2(file.id(), name, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  });
}

template <class Value>
DatasetHandle write_block_dataset(const ParallelHdf5File& file, const BlockDataset& dataset,
                                  const RowBlock& block, std::span<const Value> block_values) {
  CATENA_ASSERT(dataset.n_columns >= 1, "a dataset row has at least one column");
  CATENA_ASSERT(block_values.size() == static_cast<std::size_t>(block.count) *
                                           static_cast<std::size_t>(dataset.n_columns),
                "one row of values per block row");
  const std::string& path = file.path();
  const DataspaceHandle file_space =
      rows_space(dataset.n_rows, dataset.n_columns, path, dataset.name);
  const PropertyListHandle creation = create_property_list(H5P_DATASET_CREATE, path);
  // Parallel HDF5 allocates the whole dataset at creation; every element is written
  // below, so writing fill values first would only double the I/O.
  check_hdf5_status(H5Pset_fill_time(creation.get(), H5D_FILL_TIME_NEVER), "H5Pset_fill_time", path,
                    dataset.name);
  DatasetHandle created =
      file.agreed_create<DatasetHandle>({"H5Dcreate2", path, dataset.name}, [&] {
        return H5Dcreate2(file.id(), dataset.name, Hdf5TypesOf<Value>::in_file(), file_space.get(),
                          H5P_DEFAULT, creation.get(), H5P_DEFAULT);
      });

  if (dataset.unit != nullptr) write_string_attribute({created.get(), path}, "unit", dataset.unit);
  // Every rank sees the same n_rows, so all skip together: nothing to write, no hang.
  if (dataset.n_rows == 0) return created;

  const DataspaceHandle memory_space =
      rows_space(block.count, dataset.n_columns, path, dataset.name);
  if (block.count > 0) {
    const std::array<hsize_t, 2> start{static_cast<hsize_t>(block.begin), 0};
    const std::array<hsize_t, 2> count{static_cast<hsize_t>(block.count),
                                       static_cast<hsize_t>(dataset.n_columns)};
    check_hdf5_status(H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start.data(), nullptr,
                                          count.data(), nullptr),
                      "H5Sselect_hyperslab", path, dataset.name);
  } else {
    // A rank without rows still joins the collective write, with empty selections.
    check_hdf5_status(H5Sselect_none(file_space.get()), "H5Sselect_none", path, dataset.name);
    check_hdf5_status(H5Sselect_none(memory_space.get()), "H5Sselect_none", path, dataset.name);
  }
  try {
    file.agreed({"H5Dwrite", path, dataset.name}, [&] {
      return H5Dwrite(created.get(), Hdf5TypesOf<Value>::in_memory(), memory_space.get(),
                      file_space.get(), file.collective_transfer(), block_values.data());
    });
  } catch (const OutputError&) {
    (void)created.release();  // the file is abandoned (see the header)
    throw;
  }
  return created;
}

template DatasetHandle write_block_dataset<double>(const ParallelHdf5File&, const BlockDataset&,
                                                   const RowBlock&, std::span<const double>);
template DatasetHandle write_block_dataset<std::int64_t>(const ParallelHdf5File&,
                                                         const BlockDataset&, const RowBlock&,
                                                         std::span<const std::int64_t>);
template DatasetHandle write_block_dataset<std::int32_t>(const ParallelHdf5File&,
                                                         const BlockDataset&, const RowBlock&,
                                                         std::span<const std::int32_t>);
template DatasetHandle write_block_dataset<std::int8_t>(const ParallelHdf5File&,
                                                        const BlockDataset&, const RowBlock&,
                                                        std::span<const std::int8_t>);

}  // namespace catena::io
