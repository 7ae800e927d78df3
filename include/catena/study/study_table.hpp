#pragma once
// The results of a study: one row per case, its cost and its errors against the
// reference, written as study.csv (columns: docs/study.md, "study.csv"), and the setting a
// user should pick for an accuracy target. Pure: the measures come from case_measures.hpp.
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "catena/io/error_bar_record.hpp"
#include "catena/io/run_summary_reader.hpp"

namespace catena::study {

inline constexpr double not_measured = std::numeric_limits<double>::quiet_NaN();

// The errors of a run against the reference; NaN where the study did not measure them
// (no pantographs, no probes, a failed case). Over several pantographs or probes, each
// column holds the worst (largest magnitude, its sign kept).
struct CaseErrors {
  double force_rms = not_measured;           // N, raw contact force
  double force_max = not_measured;           // N
  double force_rms_filtered = not_measured;  // N, at the statistics' low-pass
  double force_max_filtered = not_measured;  // N
  // Relative errors of the EN 50318 statistics, in % of the reference's.
  double mean = not_measured;
  double std = not_measured;
  double stat_max = not_measured;
  double stat_min = not_measured;
  double max = not_measured;
  double min = not_measured;
  double uplift = not_measured;
  double loss = not_measured;       // percentage points of contact loss
  double probe_rms = not_measured;  // m
  double probe_max = not_measured;  // m
};

struct StudyRow {
  std::string name;     // the case's file stem under DIR/cases
  std::string role;     // "setting", "reference", "reference_check"
  std::string method;   // the plot's line: the varied keys that are not resolution keys
  std::string setting;  // the varied resolution keys ("integrator.dt=0.0005")
  bool completed = false;
  int exit_code = 0;
  std::string message;        // why it failed ("" when completed)
  double case_seconds = 0.0;  // s, the whole case (scene, statics, dynamics, output)
  io::RunWork work;           // from its output (completed cases)
  CaseErrors errors;
  // The error bar `catena run --error-bar` would give this case: Richardson's estimate from
  // the study's cases of the same method at 2 and 4 times its step, where it has both
  // (study/richardson.hpp); empty otherwise.
  std::vector<io::ErrorBarEntry> estimates;
};

// Not collective. The wall time of the time stepping per simulated second (0 if none ran).
double stepping_per_simulated_second(const io::RunWork& work);

// Not collective. The wall time of the whole run's time stepping: a run continued from a
// checkpoint records only the part after its restart, which is scaled to the whole
// simulated time at its rate (what study.csv's wall_seconds and the recommendation use).
double stepping_seconds(const io::RunWork& work);

// Not collective. One CSV field: quoted (quotes doubled) when it holds a comma, a quote or a
// line break (RFC 4180).
std::string csv_field(const std::string& text);

// Not collective. study.csv's text: a header line, then one line per row.
std::string csv_text(const std::vector<StudyRow>& rows);

// One `--target MEASURE=LIMIT`: |measure| ≤ limit.
struct Target {
  std::string measure;  // a CaseErrors field's name as in the CSV header (std, force_rms, ...)
  double limit = 0.0;   // in the measure's unit (% for statistics, N, m, points)
  std::string text;     // as given
};

// Not collective. Parses "std=1%", "sigma=1%", "force_rms_filtered=2N", "probe_rms=1e-4m",
// "loss=0.1" (the unit letter, if given, must be the measure's). Throws
// catena::InputError (key "--target") naming the argument and the accepted measures.
Target parse_target(const std::string& argument);

// Not collective. Every field of CaseErrors, in the order of study.csv's columns.
std::vector<double CaseErrors::*> error_fields();

// Not collective. The value of `measure` in `errors` (NaN if not measured).
double measure_value(const CaseErrors& errors, const std::string& measure);

// Not collective. The cheapest (least time-stepping wall time) completed "setting" row
// that meets every target with a measured value; none if no row does.
std::optional<std::size_t> recommend(const std::vector<StudyRow>& rows,
                                     const std::vector<Target>& targets);

}  // namespace catena::study
