#pragma once
// A finished case of a study, on disk beside its output (DIR/cases/NAME.result), so that
// a study killed midway resumes without redoing it: a case counts as done when its record
// exists and names the same overrides and the same scene (another study in the same
// directory, the same case with other settings, or an edited scene runs again). Written atomically
// (a temporary renamed into place): a kill leaves the old record or the new one, never half of one.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace catena::study {

struct CaseRecord {
  std::vector<std::string> overrides;  // the scene overrides the case ran with, in order
  // digest() of the scene it ran (the scene file after --set and the case's overrides,
  // model::scene_identity, and the duration): an edited scene or a changed --set runs again
  std::string scene;
  bool completed = false;     // false: the run stopped with an error
  int exit_code = 0;          // as `catena run` would exit: 0, 2 bad input, 3 numerical
  std::string message;        // the error, one line ("" when completed)
  double wall_seconds = 0.0;  // s, the whole case: scene, statics, dynamics, output
};

// Not collective. 16 hex digits of the 64-bit FNV-1a hash of `text`: the same on every
// machine and build (std::hash is not).
std::string digest(const std::string& text);

// Not collective. The record as text (the format: case_record.cpp) and back; nullopt for
// a text that is not a record of this format.
std::string record_text(const CaseRecord& record);
std::optional<CaseRecord> parse_record(const std::string& text);

// Not collective. Writes `record` to `path` atomically; throws catena::Error naming the
// path on a failed write.
void write_record(const std::filesystem::path& path, const CaseRecord& record);

// Not collective. The record at `path`; nullopt if there is none or it is not a record.
std::optional<CaseRecord> read_record(const std::filesystem::path& path);

}  // namespace catena::study
