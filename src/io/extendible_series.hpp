#pragma once
// An extendible HDF5 dataset of the time-series output (transient_writer.cpp): rows
// appended along its first dimension, collectively.
#include <hdf5.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "catena/core/error.hpp"
#include "collective_hdf5_call.hpp"
#include "hdf5_attributes.hpp"
#include "hdf5_error.hpp"
#include "hdf5_handles.hpp"
#include "hdf5_parallel_write.hpp"
#include "row_redistribution.hpp"
#include "space_probe.hpp"
#include "transient_layout.hpp"

namespace catena::io {

// An extendible dataset: rows appended along the first dimension.
class Series {
 public:
  Series() = default;
  // Collective. Creates `dataset` with no rows. shape: the per-row shape (empty: scalar
  // rows).
  Series(const ParallelHdf5File& file, const transient_layout::Dataset& dataset,
         std::vector<hsize_t> shape, hid_t type)
      : file_(&file),
        name_(dataset.path),
        path_(file.path()),
        shape_(std::move(shape)),
        type_(type) {
    const char* name = dataset.path;
    std::vector<hsize_t> dims{0}, max{H5S_UNLIMITED}, chunk{1};
    hsize_t row = 1;
    for (hsize_t n : shape_) {
      dims.push_back(n);
      max.push_back(n);
      chunk.push_back(std::max<hsize_t>(n, 1));
      row *= std::max<hsize_t>(n, 1);
    }
    // About 64 KiB chunks along time (at least one row), so appends touch few chunks.
    chunk[0] = std::max<hsize_t>(1, (64 * 1024 / 8) / row);
    const DataspaceHandle space(
        checked_hdf5_id(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), max.data()),
                        "H5Screate_simple", path_, name_));
    const PropertyListHandle create(
        checked_hdf5_id(H5Pcreate(H5P_DATASET_CREATE), "H5Pcreate", path_, name_));
    check_hdf5_status(H5Pset_chunk(create.get(), static_cast<int>(chunk.size()), chunk.data()),
                      "H5Pset_chunk", path_, name_);
    // Every appended row is written whole, so the chunks that extending allocates need no
    // fill values. Writing them would be a collective write inside H5Dset_extent, and when
    // it fails on one rank only (a full disk), HDF5 1.10 returns there without the barrier
    // that the other ranks wait in: a hang no agreement after the call can prevent.
    check_hdf5_status(H5Pset_fill_time(create.get(), H5D_FILL_TIME_NEVER), "H5Pset_fill_time",
                      path_, name_);
    const PropertyListHandle links(
        checked_hdf5_id(H5Pcreate(H5P_LINK_CREATE), "H5Pcreate", path_, name_));
    check_hdf5_status(H5Pset_create_intermediate_group(links.get(), 1),
                      "H5Pset_create_intermediate_group", path_, name_);
    dataset_ = file.agreed_create<DatasetHandle>({"H5Dcreate2", path_, name_}, [&] {
      return H5Dcreate2(file.id(), name, type, space.get(), links.get(), create.get(), H5P_DEFAULT);
    });
    if (dataset.unit)
      run_output_phase(file.comm(), [&] {
        write_string_attribute({dataset_.get(), path_}, "unit", dataset.unit);
      });
  }

  // Collective. Opens the existing `dataset` and cuts it to `rows` rows.
  Series(const ParallelHdf5File& file, const transient_layout::Dataset& dataset,
         std::vector<hsize_t> shape, hid_t type, hsize_t rows)
      : file_(&file),
        name_(dataset.path),
        path_(file.path()),
        shape_(std::move(shape)),
        type_(type),
        rows_(rows) {
    dataset_ = DatasetHandle(
        checked_hdf5_id(H5Dopen2(file.id(), dataset.path, H5P_DEFAULT), "H5Dopen2", path_, name_));
    const DataspaceHandle space(
        checked_hdf5_id(H5Dget_space(dataset_.get()), "H5Dget_space", path_, name_));
    std::vector<hsize_t> dims(shape_.size() + 1);
    const int rank = H5Sget_simple_extent_ndims(space.get());
    if (rank != static_cast<int>(dims.size()))
      throw Error(path_ + ": dataset " + name_ + " has " + std::to_string(rank) +
                  " dimensions, expected " + std::to_string(dims.size()) +
                  " (not this model's output?)");
    H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
    for (size_t k = 0; k < shape_.size(); ++k)
      if (dims[k + 1] != shape_[k])
        throw Error(path_ + ": dataset " + name_ + " has " + std::to_string(dims[k + 1]) +
                    " columns in dimension " + std::to_string(k + 1) + ", this model " +
                    std::to_string(shape_[k]) + " (the output of another model?)");
    if (dims[0] < rows)
      throw Error(path_ + ": dataset " + name_ + " has " + std::to_string(dims[0]) +
                  " rows, fewer than the checkpoint's " + std::to_string(rows) +
                  " (the output is older than the checkpoint)");
    dims[0] = rows;
    file.agreed({"H5Dset_extent", path_, name_},
                [&] { return H5Dset_extent(dataset_.get(), dims.data()); });
  }

  // Collective. Appends n_rows rows; this rank writes rows [first, first + count) of them
  // (a block along the second dimension for node/element-distributed data: `block`).
  // Both collective calls agree on their outcome: extending allocates (and fills) the new
  // chunks, so it writes too and may fail on one rank.
  void append(hid_t transfer, hsize_t n_rows, const RowBlock& block, const void* data) {
    const hsize_t old = rows_;
    rows_ += n_rows;
    std::vector<hsize_t> dims{rows_};
    for (hsize_t n : shape_) dims.push_back(n);
    file_->agreed({"H5Dset_extent", path_, name_},
                  [&] { return H5Dset_extent(dataset_.get(), dims.data()); });
    // Every rank reads the dataset's header here, so a metadata-cache sync point that the
    // extension made due runs on every rank at this call. Left to the write, it would run
    // only on the ranks that look chunks up there (those with rows to write) while the
    // others went on to the collective write: a hang (from_root, below, has the history).
    H5O_info_t header{};  // HDF5 1.10's H5O_info_t (H5Oget_info2)
    file_->agreed({"H5Oget_info2", path_, name_},
                  [&] { return H5Oget_info2(dataset_.get(), &header, H5O_INFO_BASIC); });
    const DataspaceHandle file_space(
        checked_hdf5_id(H5Dget_space(dataset_.get()), "H5Dget_space", path_, name_));
    std::vector<hsize_t> start(dims.size(), 0), count(dims);
    start[0] = old;
    count[0] = n_rows;
    if (!shape_.empty()) {
      start[1] = static_cast<hsize_t>(block.begin);
      count[1] = static_cast<hsize_t>(block.count);
    } else if (block.count == 0) {
      count[0] = 0;
    }
    hsize_t n_values = 1;
    for (hsize_t c : count) n_values *= c;
    // The memory space has the selection's shape, so HDF5 maps it onto the chunks block by
    // block; a flat one made it visit every value (H5S_select_iterate: 9 % of a linear
    // EN 50318 run). A dummy of one value when this rank writes nothing.
    const hsize_t one = 1;
    const DataspaceHandle memory(checked_hdf5_id(
        n_values > 0 ? H5Screate_simple(static_cast<int>(count.size()), count.data(), nullptr)
                     : H5Screate_simple(1, &one, nullptr),
        "H5Screate_simple", path_, name_));
    if (n_values > 0) {
      check_hdf5_status(H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start.data(), nullptr,
                                            count.data(), nullptr),
                        "H5Sselect_hyperslab", path_, name_);
    } else {
      check_hdf5_status(H5Sselect_none(file_space.get()), "H5Sselect_none", path_, name_);
      check_hdf5_status(H5Sselect_none(memory.get()), "H5Sselect_none", path_, name_);
    }
    file_->agreed({"H5Dwrite", path_, name_}, [&] {
      return H5Dwrite(dataset_.get(), type_ == H5T_STD_I32LE ? H5T_NATIVE_INT32 : H5T_NATIVE_DOUBLE,
                      memory.get(), file_space.get(), transfer, data);
    });
  }
  hsize_t rows() const { return rows_; }
  void reset() { dataset_ = DatasetHandle(); }
  // Forgets the dataset without closing it: its file is abandoned.
  void abandon() { (void)dataset_.release(); }

 private:
  const ParallelHdf5File* file_ = nullptr;
  std::string name_, path_;
  std::vector<hsize_t> shape_;
  hid_t type_ = H5T_IEEE_F64LE;
  hsize_t rows_ = 0;
  DatasetHandle dataset_;
};

}  // namespace catena::io
