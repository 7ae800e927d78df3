#pragma once
// The error bar of a dynamic run (`catena run --error-bar`; docs/accuracy.md, "Error bar
// of a run"), stored in its output as the group /error_bar: the estimated
// time-discretisation error of each quantity users read, with the observed order of
// convergence it rests on.
#include <optional>
#include <string>
#include <vector>

namespace catena::io {

struct ErrorBarEntry {
  std::string part;     // the pantograph's name, or the probe ("node 31")
  std::string measure;  // "std", "mean", ..., "force_rms_filtered", "probe_rms"
  std::string unit;     // "%" (of the run's own value), "N", "m"
  // The estimated error of the run: run − converged value for a statistic, the RMS of the
  // difference for a series.
  double estimate = 0.0;
  // The observed order it was scaled with; NaN when the three runs do not converge at one
  // order in [1/2, 6] and `estimate` is a rough size instead (study/richardson.hpp).
  double order = 0.0;
};

struct ErrorBarRecord {
  double dt = 0.0;                        // s, the run's step
  std::vector<double> coarse_dt;          // s, the steps of the comparison runs (2 dt, 4 dt)
  std::vector<std::string> coarse_files;  // their outputs
  std::vector<ErrorBarEntry> entries;
};

// Not collective (one process, the file closed elsewhere). Writes `record` into the group
// /error_bar of the complete output `path` (replacing an earlier one): attributes
// `method` = "richardson", `dt`, `coarse_dt_1`, `coarse_dt_2`, `coarse_files`, and per part
// a group /error_bar/<part> ('/' in a name written as '_') with, per entry, `<measure>`
// (the estimate), `<measure>_order` and `<measure>_unit`. Throws catena::OutputError naming
// the file if it cannot.
void write_error_bar(const std::string& path, const ErrorBarRecord& record);

// Not collective. The error bar stored in `path`, none if it has no /error_bar. Entries per
// part in the order of the parts' names, within a part in the order `catena run` writes
// (mean, std, stat_max, stat_min, max, min, uplift, force_rms_filtered, probe_rms).
// Throws catena::Error naming the file if it cannot be read.
std::optional<ErrorBarRecord> read_error_bar(const std::string& path);

}  // namespace catena::io
