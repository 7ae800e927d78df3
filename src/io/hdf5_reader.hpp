#pragma once
// Serial reads of a Catena HDF5 file: every rank that needs it opens the file read-only on
// its own (no MPI-IO), reads attributes and datasets, and gets catena::Error naming the
// file and the object when a call fails. Used for checkpoints and modal bases, whose
// readers turn such an error into the user's (a restart or a basis refused, and why).
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "hdf5_handles.hpp"

namespace catena::io {

class Hdf5Reader {
 public:
  explicit Hdf5Reader(const std::string& path);

  const std::string& path() const { return path_; }
  double real(const char* name) const;           // root attribute
  std::int64_t integer(const char* name) const;  // root attribute
  std::string text(const char* name) const;      // root string attribute
  bool has_attribute(const char* name) const;    // root attribute
  bool has(const char* name) const;              // object by absolute path
  // Names of the objects in group `name`, in HDF5's name order.
  std::vector<std::string> members(const char* name) const;
  // The numeric attributes of group `name`: floating point as reals, integers as integers.
  void numbers(const char* name, std::map<std::string, double>& reals,
               std::map<std::string, std::int64_t>& integers) const;
  // The whole dataset `name`, which must hold `expected` values.
  std::vector<double> values(const char* name, std::size_t expected) const;
  // Rows [begin, begin + count) of the 1-D dataset `name` of `n_rows` values (its size is
  // checked).
  std::vector<double> rows(const char* name, std::int64_t n_rows, std::int64_t begin,
                           std::int64_t count) const;

 private:
  void read_attribute(const char* name, hid_t type, void* value) const;
  DatasetHandle open_sized(const char* name, std::size_t expected) const;

  std::string path_;
  FileHandle file_;
};

}  // namespace catena::io
