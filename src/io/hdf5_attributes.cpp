#include "hdf5_attributes.hpp"

#include "catena/core/error.hpp"
#include "hdf5_error.hpp"
#include "hdf5_handles.hpp"

namespace catena::io {
namespace {

std::string attribute_label(const char* name) { return std::string("attribute '") + name + "'"; }

DatatypeHandle variable_length_utf8_string(const AttributeTarget& target, const char* name) {
  DatatypeHandle type(
      checked_hdf5_id(H5Tcopy(H5T_C_S1), "H5Tcopy", target.file_path, attribute_label(name)));
  check_hdf5_status(H5Tset_size(type.get(), H5T_VARIABLE), "H5Tset_size", target.file_path,
                    attribute_label(name));
  check_hdf5_status(H5Tset_cset(type.get(), H5T_CSET_UTF8), "H5Tset_cset", target.file_path,
                    attribute_label(name));
  return type;
}

// Creates the attribute with `file_type` over `space` and writes `values` (memory layout
// `memory_type`).
void create_and_write(const AttributeTarget& target, const char* name, hid_t file_type,
                      hid_t memory_type, const DataspaceHandle& space, const void* values) {
  const std::string label = attribute_label(name);
  const AttributeHandle attribute(checked_hdf5_id(
      H5Acreate2(target.object, name, file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT),
      "H5Acreate2", target.file_path, label));
  check_hdf5_status(H5Awrite(attribute.get(), memory_type, values), "H5Awrite", target.file_path,
                    label);
}

DataspaceHandle scalar_space(const AttributeTarget& target, const char* name) {
  return DataspaceHandle(
      checked_hdf5_id(H5Screate(H5S_SCALAR), "H5Screate", target.file_path, attribute_label(name)));
}

}  // namespace

void write_string_attribute(const AttributeTarget& target, const char* name,
                            const std::string& value) {
  const DatatypeHandle type = variable_length_utf8_string(target, name);
  const char* text = value.c_str();
  create_and_write(target, name, type.get(), type.get(), scalar_space(target, name), &text);
}

void write_string_list_attribute(const AttributeTarget& target, const char* name,
                                 const std::vector<std::string>& values) {
  const DatatypeHandle type = variable_length_utf8_string(target, name);
  const hsize_t n_values = values.size();
  const DataspaceHandle space(checked_hdf5_id(H5Screate_simple(1, &n_values, nullptr),
                                              "H5Screate_simple", target.file_path,
                                              attribute_label(name)));
  std::vector<const char*> texts;
  texts.reserve(values.size());
  for (const std::string& value : values) texts.push_back(value.c_str());
  // An empty list still needs a valid buffer address.
  const char* const no_text = nullptr;
  create_and_write(target, name, type.get(), type.get(), space,
                   texts.empty() ? static_cast<const void*>(&no_text) : texts.data());
}

void write_int64_attribute(const AttributeTarget& target, const char* name, std::int64_t value) {
  create_and_write(target, name, H5T_STD_I64LE, H5T_NATIVE_INT64, scalar_space(target, name),
                   &value);
}

void write_double_attribute(const AttributeTarget& target, const char* name, double value) {
  create_and_write(target, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, scalar_space(target, name),
                   &value);
}

std::optional<std::string> read_string_attribute(const AttributeTarget& target, const char* name) {
  const std::string label = attribute_label(name);
  const htri_t exists = H5Aexists(target.object, name);
  check_hdf5_status(exists, "H5Aexists", target.file_path, label);
  if (exists == 0) return std::nullopt;
  const AttributeHandle attribute(checked_hdf5_id(H5Aopen(target.object, name, H5P_DEFAULT),
                                                  "H5Aopen", target.file_path, label));
  const DatatypeHandle type(
      checked_hdf5_id(H5Aget_type(attribute.get()), "H5Aget_type", target.file_path, label));
  const DataspaceHandle space(
      checked_hdf5_id(H5Aget_space(attribute.get()), "H5Aget_space", target.file_path, label));
  if (H5Tget_class(type.get()) != H5T_STRING || H5Sget_simple_extent_npoints(space.get()) != 1)
    throw Error("'" + target.file_path + "' at " + label + ": not a single string");
  if (H5Tis_variable_str(type.get()) > 0) {
    char* text = nullptr;
    check_hdf5_status(H5Aread(attribute.get(), type.get(), &text), "H5Aread", target.file_path,
                      label);
    std::string value = text != nullptr ? text : "";
    H5free_memory(text);
    return value;
  }
  std::string buffer(H5Tget_size(type.get()), '\0');
  check_hdf5_status(H5Aread(attribute.get(), type.get(), buffer.data()), "H5Aread",
                    target.file_path, label);
  return buffer.substr(0, buffer.find('\0'));
}

}  // namespace catena::io
