#include "catena/study/study_table.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "catena/core/error.hpp"
#include "catena/study/study_plan.hpp"

namespace catena::study {
namespace {

// A measure: its CSV column, the CaseErrors field, its unit letter for --target.
struct Measure {
  const char* name;
  double CaseErrors::*field;
  const char* unit;    // "%" for the statistics' relative errors
  const char* column;  // the CSV header
};

constexpr Measure measures[] = {
    {"force_rms", &CaseErrors::force_rms, "N", "force_rms_N"},
    {"force_max", &CaseErrors::force_max, "N", "force_max_N"},
    {"force_rms_filtered", &CaseErrors::force_rms_filtered, "N", "force_rms_filtered_N"},
    {"force_max_filtered", &CaseErrors::force_max_filtered, "N", "force_max_filtered_N"},
    {"mean", &CaseErrors::mean, "%", "mean_error_percent"},
    {"std", &CaseErrors::std, "%", "std_error_percent"},
    {"stat_max", &CaseErrors::stat_max, "%", "stat_max_error_percent"},
    {"stat_min", &CaseErrors::stat_min, "%", "stat_min_error_percent"},
    {"max", &CaseErrors::max, "%", "max_error_percent"},
    {"min", &CaseErrors::min, "%", "min_error_percent"},
    {"uplift", &CaseErrors::uplift, "%", "uplift_error_percent"},
    {"loss", &CaseErrors::loss, "", "loss_difference_points"},
    {"probe_rms", &CaseErrors::probe_rms, "m", "probe_rms_m"},
    {"probe_max", &CaseErrors::probe_max, "m", "probe_max_m"},
};

const Measure* find_measure(const std::string& name) {
  const std::string canonical = name == "sigma" ? "std" : name;
  for (const Measure& m : measures)
    if (canonical == m.name) return &m;
  return nullptr;
}

std::string accepted_measures() {
  std::string out;
  for (const Measure& m : measures) {
    if (!out.empty()) out += ", ";
    out.append(m.name).append(" (").append(*m.unit ? m.unit : "points").append(")");
  }
  return out + "; sigma is std";
}

std::string number(double x) { return std::isfinite(x) ? number_text(x) : ""; }

// The error-bar columns: an estimate (or its order) of one measure.
struct EstimateColumn {
  const char* measure;
  bool order;
  const char* column;
};
constexpr EstimateColumn estimate_columns[] = {
    {"std", false, "std_error_estimate_percent"},
    {"std", true, "std_estimate_order"},
    {"force_rms_filtered", false, "force_rms_filtered_estimate_N"},
    {"force_rms_filtered", true, "force_rms_filtered_estimate_order"},
    {"probe_rms", false, "probe_rms_estimate_m"},
    {"probe_rms", true, "probe_rms_estimate_order"},
};

double estimate_cell(const StudyRow& r, const EstimateColumn& c) {
  for (const io::ErrorBarEntry& e : r.estimates)
    if (e.measure == c.measure) return c.order ? e.order : e.estimate;
  return not_measured;
}

}  // namespace

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) {
    out += c;
    if (c == '"') out += c;  // a quote is doubled
  }
  return out + "\"";
}

double stepping_per_simulated_second(const io::RunWork& work) {
  const double simulated = work.t_reached - work.t_started;
  return simulated > 0.0 ? work.stepping_seconds / simulated : 0.0;
}

double stepping_seconds(const io::RunWork& work) {
  return work.t_started > 0.0 ? stepping_per_simulated_second(work) * work.t_reached
                              : work.stepping_seconds;
}

std::string csv_text(const std::vector<StudyRow>& rows) {
  std::string out =
      "case,role,method,setting,status,steps,rejected_steps,wall_seconds,"
      "wall_per_simulated_second,newton_iterations,factorisations,residual_evaluations,"
      "linear_solves,case_wall_seconds,n_ranks";
  for (const Measure& m : measures) out += std::string(",") + m.column;
  for (const EstimateColumn& c : estimate_columns) out += std::string(",") + c.column;
  out += ",message\n";
  for (const StudyRow& r : rows) {
    const io::RunWork& w = r.work;
    const bool ok = r.completed;
    auto cell = [&](const std::string& text) { out.append(",").append(text); };
    auto count = [&](std::int64_t n) { cell(ok ? std::to_string(n) : std::string()); };
    out += csv_field(r.name);
    cell(csv_field(r.role));
    cell(csv_field(r.method));
    cell(csv_field(r.setting));
    cell(ok ? std::string("completed") : "failed (exit " + std::to_string(r.exit_code) + ")");
    count(w.steps_accepted);
    count(w.steps_rejected);
    cell(ok ? number(stepping_seconds(w)) : std::string());
    cell(ok ? number(stepping_per_simulated_second(w)) : std::string());
    count(w.newton_iterations);
    count(w.factorizations);
    count(w.residual_evaluations);
    count(w.linear_solves);
    cell(number(r.case_seconds));
    count(w.n_ranks);
    for (const Measure& m : measures) cell(number(r.errors.*m.field));
    for (const EstimateColumn& c : estimate_columns) cell(number(estimate_cell(r, c)));
    cell(csv_field(r.message));
    out += "\n";
  }
  return out;
}

Target parse_target(const std::string& argument) {
  const auto eq = argument.find('=');
  const std::string name = argument.substr(0, eq);
  const Measure* m = find_measure(name);
  if (eq == std::string::npos || !m)
    throw InputError({"", 0, "--target"}, "'" + argument +
                                              "': expected MEASURE=LIMIT with MEASURE one of " +
                                              accepted_measures() + " (e.g. std=1%)");
  std::string text = argument.substr(eq + 1);
  const std::string unit = m->unit;
  if (!unit.empty() && text.size() > unit.size() &&
      text.compare(text.size() - unit.size(), unit.size(), unit) == 0)
    text.resize(text.size() - unit.size());
  double limit = 0.0;
  const auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), limit);
  if (ec != std::errc() || p != text.data() + text.size() || !(limit > 0.0) ||
      !std::isfinite(limit))
    throw InputError({"", 0, "--target"},
                     "'" + argument + "': the limit must be a positive number" +
                         (unit.empty() ? "" : ", optionally followed by " + unit) + " (e.g. " +
                         m->name + "=" + (unit == "%" ? "1%" : "0.5" + unit) + ")");
  return {m->name, limit, argument};
}

std::vector<double CaseErrors::*> error_fields() {
  std::vector<double CaseErrors::*> fields;
  for (const Measure& m : measures) fields.push_back(m.field);
  return fields;
}

double measure_value(const CaseErrors& errors, const std::string& measure) {
  const Measure* m = find_measure(measure);
  return m ? errors.*m->field : not_measured;
}

std::optional<std::size_t> recommend(const std::vector<StudyRow>& rows,
                                     const std::vector<Target>& targets) {
  std::optional<std::size_t> best;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const StudyRow& r = rows[i];
    if (r.role.rfind("setting", 0) != 0 || !r.completed) continue;
    const bool meets = std::all_of(targets.begin(), targets.end(), [&](const Target& t) {
      const double v = measure_value(r.errors, t.measure);
      return std::isfinite(v) && std::abs(v) <= t.limit;
    });
    if (meets && (!best || stepping_seconds(r.work) < stepping_seconds(rows[*best].work))) best = i;
  }
  return best;
}

}  // namespace catena::study
