// check_scene_text: rejects files that are not YAML text before the parser sees them, so
// that a binary file, a minified blob or an empty file get a message that says so.
#include <cstdint>
#include <string_view>

#include "catena/core/error.hpp"
#include "catena/model/scene_reader.hpp"

namespace catena::model {
namespace {

[[noreturn]] void fail(const std::string& file_label, int line, const std::string& message) {
  throw InputError(InputLocation{file_label, line, ""}, message);
}

// Length of the UTF-8 sequence starting at text[i], or 0 if it is not well formed
// (overlong encodings, surrogates and code points above U+10FFFF included, per RFC 3629).
std::size_t utf8_sequence_length(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<std::uint8_t>(text[k]); };
  const std::uint8_t lead = byte(i);
  if (lead < 0x80) return 1;
  std::size_t length = 0;
  std::uint8_t second_min = 0x80, second_max = 0xBF;
  if (lead >= 0xC2 && lead <= 0xDF) {
    length = 2;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3;
    if (lead == 0xE0) second_min = 0xA0;  // overlong
    if (lead == 0xED) second_max = 0x9F;  // UTF-16 surrogates
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4;
    if (lead == 0xF0) second_min = 0x90;  // overlong
    if (lead == 0xF4) second_max = 0x8F;  // above U+10FFFF
  } else {
    return 0;
  }
  if (i + length > text.size()) return 0;
  if (byte(i + 1) < second_min || byte(i + 1) > second_max) return 0;
  for (std::size_t k = 2; k < length; ++k)
    if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return 0;
  return length;
}

// A line without content: blank, a comment, or a bare document marker ("---", "...",
// optionally followed by a comment; "--- {a: 1}" has content).
bool is_ignorable_line(std::string_view line) {
  const auto skip_blanks = [](std::string_view& s) {
    const std::size_t first = s.find_first_not_of(" \t\r");
    s.remove_prefix(first == std::string_view::npos ? s.size() : first);
  };
  skip_blanks(line);
  if (line.starts_with("---") || line.starts_with("...")) {
    line.remove_prefix(3);
    if (!line.empty() && line.front() != ' ' && line.front() != '\t' && line.front() != '\r')
      return false;  // e.g. "----" or "...x": content
    skip_blanks(line);
  }
  return line.empty() || line.front() == '#';
}

}  // namespace

void check_scene_text(const std::string& text, const std::string& file_label) {
  if (text.size() > max_scene_bytes)
    fail(file_label, 0,
         "scene is " + std::to_string(text.size()) + " bytes; at most " +
             std::to_string(max_scene_bytes) + " bytes (64 MiB) are accepted");

  std::string_view body = text;
  if (body.starts_with("\xEF\xBB\xBF")) body.remove_prefix(3);  // UTF-8 byte-order mark

  int line = 1;
  std::size_t line_start = 0;
  bool has_content = false;
  for (std::size_t i = 0; i <= body.size();) {
    if (i == body.size() || body[i] == '\n') {
      const std::size_t length = i - line_start;
      if (length > max_scene_line_bytes)
        fail(file_label, line,
             "line " + std::to_string(line) + " is " + std::to_string(length) +
                 " bytes long; at most " + std::to_string(max_scene_line_bytes) +
                 " bytes per line are accepted (is this a scene file?)");
      if (!has_content) has_content = !is_ignorable_line(body.substr(line_start, length));
      ++line;
      line_start = ++i;
      continue;
    }
    if (body[i] == '\0')
      fail(file_label, line,
           "file is binary (NUL byte at line " + std::to_string(line) + "); a scene is YAML text");
    const std::size_t n = utf8_sequence_length(body, i);
    if (n == 0)
      fail(file_label, line,
           "file is binary (not valid UTF-8 at line " + std::to_string(line) +
               "); a scene is YAML text in UTF-8");
    i += n;
  }
  if (!has_content)
    fail(file_label, 0, "scene is empty (only blank lines and comments); see docs/scene.md");
}

}  // namespace catena::model
