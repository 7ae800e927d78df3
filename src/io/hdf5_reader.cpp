#include "hdf5_reader.hpp"

#include <array>

#include "catena/core/error.hpp"
#include "hdf5_error.hpp"

namespace catena::io {
namespace {

herr_t collect_link(hid_t, const char* name, const H5L_info_t*, void* out) {
  static_cast<std::vector<std::string>*>(out)->emplace_back(name);
  return 0;
}

herr_t collect_attribute(hid_t, const char* name, const H5A_info_t*, void* out) {
  static_cast<std::vector<std::string>*>(out)->emplace_back(name);
  return 0;
}

}  // namespace

Hdf5Reader::Hdf5Reader(const std::string& path) : path_(path) {
  file_ = FileHandle(
      checked_hdf5_id(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), "H5Fopen", path));
}

double Hdf5Reader::real(const char* name) const {
  double value = 0.0;
  read_attribute(name, H5T_NATIVE_DOUBLE, &value);
  return value;
}

std::int64_t Hdf5Reader::integer(const char* name) const {
  std::int64_t value = 0;
  read_attribute(name, H5T_NATIVE_INT64, &value);
  return value;
}

bool Hdf5Reader::has_attribute(const char* name) const { return H5Aexists(file_.get(), name) > 0; }

std::string Hdf5Reader::text(const char* name) const {
  const AttributeHandle a(
      checked_hdf5_id(H5Aopen(file_.get(), name, H5P_DEFAULT), "H5Aopen", path_, name));
  const DatatypeHandle type(checked_hdf5_id(H5Aget_type(a.get()), "H5Aget_type", path_, name));
  if (H5Tget_class(type.get()) != H5T_STRING)
    throw Error(path_ + ": attribute " + name + " is not a string");
  if (H5Tis_variable_str(type.get()) > 0) {
    char* value = nullptr;
    check_hdf5_status(H5Aread(a.get(), type.get(), &value), "H5Aread", path_, name);
    std::string out = value ? value : "";
    H5free_memory(value);
    return out;
  }
  // A fixed-length string (written by another tool): its size in bytes, maybe unterminated.
  std::string out(H5Tget_size(type.get()), '\0');
  check_hdf5_status(H5Aread(a.get(), type.get(), out.data()), "H5Aread", path_, name);
  return out.substr(0, out.find('\0'));
}

bool Hdf5Reader::has(const char* name) const {
  return H5Lexists(file_.get(), name, H5P_DEFAULT) > 0;
}

std::vector<std::string> Hdf5Reader::members(const char* name) const {
  std::vector<std::string> out;
  check_hdf5_status(H5Literate_by_name(file_.get(), name, H5_INDEX_NAME, H5_ITER_INC, nullptr,
                                       collect_link, &out, H5P_DEFAULT),
                    "H5Literate_by_name", path_, name);
  return out;
}

void Hdf5Reader::numbers(const char* name, std::map<std::string, double>& reals,
                         std::map<std::string, std::int64_t>& integers) const {
  const GroupHandle g(
      checked_hdf5_id(H5Gopen2(file_.get(), name, H5P_DEFAULT), "H5Gopen2", path_, name));
  std::vector<std::string> names;
  check_hdf5_status(
      H5Aiterate2(g.get(), H5_INDEX_NAME, H5_ITER_INC, nullptr, collect_attribute, &names),
      "H5Aiterate2", path_, name);
  for (const std::string& n : names) {
    const AttributeHandle a(
        checked_hdf5_id(H5Aopen(g.get(), n.c_str(), H5P_DEFAULT), "H5Aopen", path_, n));
    const DatatypeHandle type(checked_hdf5_id(H5Aget_type(a.get()), "H5Aget_type", path_, n));
    if (H5Tget_class(type.get()) == H5T_FLOAT)
      check_hdf5_status(H5Aread(a.get(), H5T_NATIVE_DOUBLE, &reals[n]), "H5Aread", path_, n);
    else
      check_hdf5_status(H5Aread(a.get(), H5T_NATIVE_INT64, &integers[n]), "H5Aread", path_, n);
  }
}

DatasetHandle Hdf5Reader::open_sized(const char* name, std::size_t expected) const {
  DatasetHandle d(
      checked_hdf5_id(H5Dopen2(file_.get(), name, H5P_DEFAULT), "H5Dopen2", path_, name));
  const DataspaceHandle space(checked_hdf5_id(H5Dget_space(d.get()), "H5Dget_space", path_, name));
  if (static_cast<std::size_t>(H5Sget_simple_extent_npoints(space.get())) != expected)
    throw Error(path_ + ": dataset " + name + " has " +
                std::to_string(H5Sget_simple_extent_npoints(space.get())) + " values, expected " +
                std::to_string(expected));
  return d;
}

std::vector<double> Hdf5Reader::values(const char* name, std::size_t expected) const {
  std::vector<double> out(expected);
  const DatasetHandle d = open_sized(name, expected);
  if (expected > 0)
    check_hdf5_status(
        H5Dread(d.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()), "H5Dread",
        path_, name);
  return out;
}

std::vector<double> Hdf5Reader::rows(const char* name, std::int64_t n_rows, std::int64_t begin,
                                     std::int64_t count) const {
  CATENA_ASSERT(begin >= 0 && count >= 0 && begin + count <= n_rows, "rows inside the dataset");
  std::vector<double> out(static_cast<std::size_t>(count));
  const DatasetHandle d = open_sized(name, static_cast<std::size_t>(n_rows));
  if (count == 0) return out;
  const DataspaceHandle file_space(
      checked_hdf5_id(H5Dget_space(d.get()), "H5Dget_space", path_, name));
  const std::array<hsize_t, 1> start{static_cast<hsize_t>(begin)},
      size{static_cast<hsize_t>(count)};
  check_hdf5_status(H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start.data(), nullptr,
                                        size.data(), nullptr),
                    "H5Sselect_hyperslab", path_, name);
  const DataspaceHandle memory_space(
      checked_hdf5_id(H5Screate_simple(1, size.data(), nullptr), "H5Screate_simple", path_, name));
  check_hdf5_status(H5Dread(d.get(), H5T_NATIVE_DOUBLE, memory_space.get(), file_space.get(),
                            H5P_DEFAULT, out.data()),
                    "H5Dread", path_, name);
  return out;
}

void Hdf5Reader::read_attribute(const char* name, hid_t type, void* value) const {
  const AttributeHandle a(
      checked_hdf5_id(H5Aopen(file_.get(), name, H5P_DEFAULT), "H5Aopen", path_, name));
  check_hdf5_status(H5Aread(a.get(), type, value), "H5Aread", path_, name);
}

}  // namespace catena::io
