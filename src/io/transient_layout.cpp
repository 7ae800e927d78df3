#include "transient_layout.hpp"

#include <optional>

#include "catena/core/error.hpp"
#include "hdf5_attributes.hpp"

namespace catena::io::transient_layout {

void require_transient_format(hid_t file, const std::string& path) {
  const AttributeTarget root{file, path};
  const std::optional<std::string> found = read_string_attribute(root, root_attribute::format);
  if (found == format) return;
  const InputLocation where{path, 0, root_attribute::format};
  const std::string expected = std::string("expected '") + format + "'";
  if (found)
    throw InputError(where, "not a Catena dynamic output (format '" + *found + "', " + expected +
                                ", the time series of this Catena)");
  if (read_string_attribute(root, root_attribute::analysis) == analysis_dynamic)
    throw InputError(where, "missing (" + expected +
                                "): a time series written by an older Catena, before the "
                                "format was recorded; run the scene again");
  throw InputError(where, "missing: not a Catena dynamic output (" + expected + ")");
}

}  // namespace catena::io::transient_layout
