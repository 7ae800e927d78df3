#include "output_name.hpp"

#include <algorithm>

namespace catena::model::detail {

std::string read_output_name(const Field& name, const std::string& fallback,
                             const std::string& what) {
  const std::string text = name.text_or(fallback);
  if (text.find('/') != std::string::npos || text == "." || text == "..")
    name.fail(what + "'s name names its output group; got '" + text +
              "', expected a name without '/' (and not '.' or '..')");
  // It heads CSV columns, figure titles and console lines: a newline split the CSV's rows,
  // a 5000-character name overflowed matplotlib's title.
  constexpr std::size_t kLongest = 64;
  const bool control = std::any_of(text.begin(), text.end(), [](char c) {
    return static_cast<unsigned char>(c) < 0x20 || c == 0x7f;
  });
  if (control || text.size() > kLongest)
    name.fail(what + "'s name heads its output's columns and figures; got " +
              (control ? std::string("one with a control character (a line break, a tab, ...)")
                       : std::to_string(text.size()) + " characters") +
              ", expected at most 64 characters and none of them a control character");
  return text;
}

}  // namespace catena::model::detail
