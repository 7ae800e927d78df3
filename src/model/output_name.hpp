#pragma once
// The names of scene items that name an HDF5 group in the output (`/bodies/<name>`,
// `/sliders/<name>`), read alike.
#include <string>

#include "yaml_fields.hpp"

namespace catena::model::detail {

// Not collective. The name at `name`, or `fallback` if absent; refused (naming `what`, "a
// body") if it holds '/' or is '.' or '..', which no group can be named.
std::string read_output_name(const Field& name, const std::string& fallback,
                             const std::string& what);

}  // namespace catena::model::detail
