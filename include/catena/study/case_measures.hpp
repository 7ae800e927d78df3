#pragma once
// The errors of a case's output against the reference's (docs/study.md, "Error
// measures"): per pantograph, the contact force's difference over the evaluation section,
// raw and low-pass filtered, and the relative error of each EN 50318 statistic; per probe
// node, the distance between the two trajectories. Reads the files serially (one rank).
#include <cstdint>
#include <string>
#include <vector>

#include "catena/io/contact_run_reader.hpp"
#include "catena/io/run_summary_reader.hpp"
#include "catena/post/contact_statistics.hpp"
#include "catena/study/study_table.hpp"

namespace catena::study {

// The errors of one part of a run: a pantograph (its name) or a probe ("node 31").
struct PartErrors {
  std::string name;
  CaseErrors errors;  // the pantograph's measures, or the probe's
};

// Not collective. Each measure's worst (largest magnitude, its sign kept) over the parts.
CaseErrors worst_of(const std::vector<PartErrors>& parts);

class ReferenceRun {
 public:
  // Not collective. Reads the reference output `path`: its contact forces if it has
  // pantographs, the tracks of `probes` (scene node ids; none given and no pantographs:
  // the node that moves most). Throws catena::InputError naming the file for a file that is
  // not a complete dynamic output or lacks a probe node.
  ReferenceRun(const std::string& path, std::vector<std::int64_t> probes, double cutoff_hz);

  // Not collective. The errors of the run whose output is `path`. Throws catena::InputError
  // naming that file when it cannot be compared (another set of pantographs, a record that
  // ends early, sampling too coarse for the cutoff).
  CaseErrors errors_of(const std::string& path) const;
  // Not collective. The same per part: each pantograph (in the reference's order), then
  // each probe.
  std::vector<PartErrors> errors_by_part(const std::string& path) const;

  const std::vector<std::int64_t>& probes() const { return probes_; }
  bool has_pantographs() const { return has_pantographs_; }
  const post::EvaluationSection& section() const { return section_; }

 private:
  std::string path_;
  double cutoff_hz_ = 20.0;
  bool has_pantographs_ = false;
  io::ContactRun contact_;
  std::vector<post::ContactStatistics> statistics_;  // per pantograph
  post::EvaluationSection section_;
  std::vector<std::int64_t> probes_;
  std::vector<io::NodeTrack> tracks_;
};

}  // namespace catena::study
