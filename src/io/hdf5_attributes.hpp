#pragma once
// Attributes of HDF5 objects (the root group, groups, datasets): scalars, strings and
// lists of strings. Strings are variable-length UTF-8, so h5py returns them as str.
//
// Collective when the file is open for parallel access: every rank must make the same
// calls with the same values, because each rank keeps its own copy of the file's metadata
// (the writer broadcasts rank 0's values beforehand to guarantee it).
#include <hdf5.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace catena::io {

// Where attributes go, and the file path that errors name.
struct AttributeTarget {
  hid_t object = H5I_INVALID_HID;
  std::string file_path;
};

void write_string_attribute(const AttributeTarget& target, const char* name,
                            const std::string& value);
void write_string_list_attribute(const AttributeTarget& target, const char* name,
                                 const std::vector<std::string>& values);
void write_int64_attribute(const AttributeTarget& target, const char* name, std::int64_t value);
void write_double_attribute(const AttributeTarget& target, const char* name, double value);

// Not collective. The string attribute `name` of target.object, variable- or fixed-length
// (h5py writes either); nothing if the object has no such attribute. Throws catena::Error
// naming the file and the attribute if it is not a single string or cannot be read.
std::optional<std::string> read_string_attribute(const AttributeTarget& target, const char* name);

}  // namespace catena::io
