#include "catena/study/case_record.hpp"

#include <charconv>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "catena/io/atomic_file.hpp"
#include "catena/study/study_plan.hpp"

namespace catena::study {
namespace {

// First line of every record; another text is not a record (and is run again).
constexpr const char* header = "catena-study-case 1";

std::string one_line(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  return text;
}

}  // namespace

std::string digest(const std::string& text) {
  std::uint64_t hash = 0xcbf29ce484222325ULL;  // FNV-1a, 64 bits
  for (unsigned char c : text) {
    hash ^= c;
    hash *= 0x100000001b3ULL;
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
  return hex;
}

// One "name: value" per line after the header; an override per `override:` line, in order.
std::string record_text(const CaseRecord& record) {
  std::string out = std::string(header) + "\n";
  out += "status: " + std::string(record.completed ? "completed" : "failed") + "\n";
  out += "exit_code: " + std::to_string(record.exit_code) + "\n";
  out += "wall_seconds: " + number_text(record.wall_seconds) + "\n";
  out += "message: " + one_line(record.message) + "\n";
  out += "scene: " + record.scene + "\n";
  for (const std::string& o : record.overrides) out += "override: " + one_line(o) + "\n";
  return out;
}

std::optional<CaseRecord> parse_record(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  if (!std::getline(in, line) || line != header) return std::nullopt;
  CaseRecord r;
  bool has_status = false;
  while (std::getline(in, line)) {
    const auto colon = line.find(": ");
    if (colon == std::string::npos) return std::nullopt;
    const std::string name = line.substr(0, colon);
    const std::string value = line.substr(colon + 2);
    if (name == "status") {
      if (value != "completed" && value != "failed") return std::nullopt;
      r.completed = value == "completed";
      has_status = true;
    } else if (name == "exit_code") {
      const auto [p, ec] = std::from_chars(value.data(), value.data() + value.size(), r.exit_code);
      if (ec != std::errc() || p != value.data() + value.size()) return std::nullopt;
    } else if (name == "wall_seconds") {
      const auto [p, ec] =
          std::from_chars(value.data(), value.data() + value.size(), r.wall_seconds);
      if (ec != std::errc() || p != value.data() + value.size()) return std::nullopt;
    } else if (name == "message") {
      r.message = value;
    } else if (name == "scene") {
      r.scene = value;
    } else if (name == "override") {
      r.overrides.push_back(value);
    } else {
      return std::nullopt;
    }
  }
  if (!has_status) return std::nullopt;
  return r;
}

void write_record(const std::filesystem::path& path, const CaseRecord& record) {
  io::write_file_atomically(path, record_text(record));
}

std::optional<CaseRecord> read_record(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  return parse_record(text.str());
}

}  // namespace catena::study
