#include "output_name.hpp"

namespace catena::model::detail {

std::string read_output_name(const Field& name, const std::string& fallback,
                             const std::string& what) {
  const std::string text = name.text_or(fallback);
  if (text.find('/') != std::string::npos || text == "." || text == "..")
    name.fail(what + "'s name names its output group; got '" + text +
              "', expected a name without '/' (and not '.' or '..')");
  return text;
}

}  // namespace catena::model::detail
