#pragma once
// A Catena time-series file opened for reading on one rank (serial HDF5), with the checks
// and error messages every reader of it shares: each failure is a catena::InputError that
// names the file and the object (docs/output.md, "Time series"). Internal to the io layer:
// contact_run_reader.cpp (`catena stats`) and run_summary_reader.cpp (`catena study`).
#include <hdf5.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "catena/core/error.hpp"
#include "hdf5_attributes.hpp"
#include "hdf5_handles.hpp"
#include "transient_layout.hpp"

namespace catena::io {

class TimeSeriesFile {
 public:
  explicit TimeSeriesFile(std::string path) : path_(std::move(path)), file_(open(path_)) {}

  [[noreturn]] void fail(const std::string& object, const std::string& message) const {
    throw InputError({path_, 0, object}, message);
  }

  bool has_link(const char* name) const {
    // Checks each level, so "/a/b" is false (not an error) when "/a" is missing.
    std::string partial;
    std::string rest = name;
    while (!rest.empty()) {
      const auto slash = rest.find('/', 1);
      partial += rest.substr(0, slash);
      rest = slash == std::string::npos ? "" : rest.substr(slash);
      if (H5Lexists(file_.get(), partial.c_str(), H5P_DEFAULT) <= 0) return false;
    }
    return true;
  }
  bool has_attribute(hid_t object, const char* name) const { return H5Aexists(object, name) > 0; }
  hid_t root() const { return file_.get(); }

  std::string text_attribute(hid_t object, const char* name, const std::string& where) const {
    std::optional<std::string> value;
    try {
      value = read_string_attribute({object, path_}, name);
    } catch (const Error& e) {
      fail(where, e.what());
    }
    if (!value) fail(where, std::string("cannot open attribute ") + name);
    return *value;
  }

  template <class T>
  T number_attribute(hid_t object, const char* name, const std::string& where) const {
    const AttributeHandle a(H5Aopen(object, name, H5P_DEFAULT));
    if (a.get() < 0) fail(where, std::string("cannot open attribute ") + name);
    const DataspaceHandle space(H5Aget_space(a.get()));
    const DatatypeHandle type(H5Aget_type(a.get()));
    const H5T_class_t cls = H5Tget_class(type.get());
    if (H5Sget_simple_extent_npoints(space.get()) != 1 || (cls != H5T_INTEGER && cls != H5T_FLOAT))
      fail(where, std::string("attribute ") + name + " is not a single number");
    T value{};
    const hid_t memory = std::is_same_v<T, double> ? H5T_NATIVE_DOUBLE : H5T_NATIVE_INT64;
    if (H5Aread(a.get(), memory, &value) < 0)
      fail(where, std::string("cannot read attribute ") + name);
    return value;
  }

  std::vector<hsize_t> dims(const char* name) const {
    const DatasetHandle d = open_dataset(name);
    const DataspaceHandle space(H5Dget_space(d.get()));
    const int rank = H5Sget_simple_extent_ndims(space.get());
    if (rank < 0) fail(name, "cannot read the dataset's shape");
    std::vector<hsize_t> out(static_cast<std::size_t>(rank));
    H5Sget_simple_extent_dims(space.get(), out.data(), nullptr);
    return out;
  }

  // The whole dataset as doubles (float or integer in the file), checked against `shape`.
  std::vector<double> doubles(const char* name, const std::vector<hsize_t>& shape) const {
    return read<double>(name, shape, H5T_FLOAT, H5T_NATIVE_DOUBLE);
  }
  std::vector<std::int64_t> integers(const char* name, const std::vector<hsize_t>& shape) const {
    return read<std::int64_t>(name, shape, H5T_INTEGER, H5T_NATIVE_INT64);
  }

  // z of the given nodes (sorted, unique) at every sample of /samples/positions, one read:
  // out[k * nodes.size() + j] is z of nodes[j] at sample k (HDF5 maps a union selection in
  // the file's row-major order).
  std::vector<double> node_heights(const std::vector<hsize_t>& nodes, hsize_t n_samples) const {
    const DatasetHandle d = open_dataset(transient_layout::positions.path);
    const DataspaceHandle file_space(H5Dget_space(d.get()));
    H5Sselect_none(file_space.get());
    for (hsize_t node : nodes) {
      const hsize_t start[3] = {0, node, 2};
      const hsize_t count[3] = {n_samples, 1, 1};
      if (H5Sselect_hyperslab(file_space.get(), H5S_SELECT_OR, start, nullptr, count, nullptr) < 0)
        fail(transient_layout::positions.path, "cannot select the registration nodes");
    }
    const hsize_t memory_dims[2] = {n_samples, nodes.size()};
    const DataspaceHandle memory_space(H5Screate_simple(2, memory_dims, nullptr));
    std::vector<double> out(n_samples * nodes.size());
    if (!out.empty() && H5Dread(d.get(), H5T_NATIVE_DOUBLE, memory_space.get(), file_space.get(),
                                H5P_DEFAULT, out.data()) < 0)
      fail(transient_layout::positions.path, "cannot read the registration nodes' positions");
    return out;
  }

  // The hyperslab [start, start + count) of a dataset as doubles, row-major.
  std::vector<double> block(const char* name, const std::vector<hsize_t>& start,
                            const std::vector<hsize_t>& count) const {
    const DatasetHandle d = open_dataset(name);
    const DataspaceHandle file_space(H5Dget_space(d.get()));
    if (H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start.data(), nullptr, count.data(),
                            nullptr) < 0)
      fail(name, "cannot select a block of the dataset");
    const DataspaceHandle memory_space(
        H5Screate_simple(static_cast<int>(count.size()), count.data(), nullptr));
    std::size_t n = 1;
    for (hsize_t c : count) n *= static_cast<std::size_t>(c);
    std::vector<double> out(n);
    if (n > 0 && H5Dread(d.get(), H5T_NATIVE_DOUBLE, memory_space.get(), file_space.get(),
                         H5P_DEFAULT, out.data()) < 0)
      fail(name, "cannot read a block of the dataset");
    return out;
  }

  GroupHandle open_group(const char* name) const {
    GroupHandle g(H5Gopen2(file_.get(), name, H5P_DEFAULT));
    if (g.get() < 0) fail(name, "not a group");
    return g;
  }

 private:
  static hid_t open(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (!fs::exists(path, ec)) throw InputError({path, 0, ""}, "no such file");
    if (fs::is_directory(path, ec)) throw InputError({path, 0, ""}, "is a directory");
    if (H5Fis_hdf5(path.c_str()) <= 0)
      throw InputError({path, 0, ""}, "not an HDF5 file (or not readable)");
    const hid_t id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (id < 0) throw InputError({path, 0, ""}, "cannot open the HDF5 file for reading");
    return id;
  }

  DatasetHandle open_dataset(const char* name) const {
    DatasetHandle d(H5Dopen2(file_.get(), name, H5P_DEFAULT));
    if (d.get() < 0) fail(name, "cannot open the dataset");
    return d;
  }

  template <class T>
  std::vector<T> read(const char* name, const std::vector<hsize_t>& shape, H5T_class_t kind,
                      hid_t memory_type) const {
    const DatasetHandle d = open_dataset(name);
    const DatatypeHandle type(H5Dget_type(d.get()));
    const H5T_class_t cls = H5Tget_class(type.get());
    if (cls != kind && !(kind == H5T_FLOAT && cls == H5T_INTEGER))
      fail(name, kind == H5T_FLOAT ? "not a numeric dataset" : "not an integer dataset");
    const std::vector<hsize_t> found = dims(name);
    if (found != shape) {
      auto text = [](const std::vector<hsize_t>& s) {
        std::ostringstream os;
        os << "(";
        for (std::size_t i = 0; i < s.size(); ++i) os << (i ? ", " : "") << s[i];
        os << (s.size() == 1 ? ",)" : ")");
        return os.str();
      };
      fail(name, "shape " + text(found) + ", expected " + text(shape));
    }
    std::size_t n = 1;
    for (hsize_t s : shape) n *= static_cast<std::size_t>(s);
    std::vector<T> out(n);
    if (n > 0 && H5Dread(d.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) < 0)
      fail(name, "cannot read the dataset");
    return out;
  }

  std::string path_;
  FileHandle file_;
};

// The status of a dynamic run's output (root attribute status: "running" while it runs or
// after a crash, then "complete", "interrupted" or "failed: ..."); throws unless the file is
// a dynamic run's output (analysis = "dynamic"). Call after the format check.
inline std::string dynamic_output_status(const TimeSeriesFile& r) {
  const std::string not_dynamic = "not a Catena dynamic output";
  const char* analysis_name = transient_layout::root_attribute::analysis;
  if (!r.has_attribute(r.root(), analysis_name))
    r.fail("", not_dynamic + " (no root attribute analysis = \"dynamic\")");
  const std::string analysis = r.text_attribute(r.root(), analysis_name, analysis_name);
  if (analysis != transient_layout::analysis_dynamic)
    r.fail(analysis_name, not_dynamic + " (analysis = '" + analysis + "')");
  const char* status_name = transient_layout::root_attribute::status;
  if (!r.has_attribute(r.root(), status_name))
    r.fail(status_name, "missing: the file was not written by a complete dynamic run");
  return r.text_attribute(r.root(), status_name, status_name);
}

// Throws unless the file is the output of a dynamic run that completed (root attributes
// analysis = "dynamic", status = "complete"); call after the format check.
inline void check_is_complete_dynamic_output(const TimeSeriesFile& r) {
  const std::string status = dynamic_output_status(r);
  if (status != "complete")
    r.fail(transient_layout::root_attribute::status,
           "the run's status is '" + status + "', not 'complete': statistics need a finished run");
}

}  // namespace catena::io
