#include "catena/study/richardson.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <string>
#include <string_view>

namespace catena::study {
namespace {

// 2ᵖ for p in [1/2, 6]: the observed orders an estimate is scaled with.
constexpr double kLowest = 1.4142135623730951, kHighest = 64.0;

}  // namespace

void richardson(double at_2dt, double at_4dt, bool signed_difference, io::ErrorBarEntry& out) {
  out.order = std::numeric_limits<double>::quiet_NaN();
  if (at_2dt == 0.0) {  // the runs at h and 2h agree: nothing to scale
    out.estimate = 0.0;
    return;
  }
  const double two_p = signed_difference ? (at_4dt - at_2dt) / at_2dt : at_4dt / at_2dt - 1.0;
  if (!(two_p > 0.0)) {  // differences of opposite sign (or a NaN): no order
    out.estimate = at_2dt;
    return;
  }
  if (two_p >= kLowest && two_p <= kHighest) out.order = std::log2(two_p);
  out.estimate = at_2dt / (std::clamp(two_p, kLowest, kHighest) - 1.0);
}

std::vector<io::ErrorBarEntry> richardson_error_bar(const std::vector<PartErrors>& at_2dt,
                                                    const std::vector<PartErrors>& at_4dt) {
  struct Measure {
    const char* name;
    const char* unit;
    double CaseErrors::*field;
    bool signed_difference;
  };
  static constexpr Measure measures[] = {
      {"mean", "%", &CaseErrors::mean, true},
      {"std", "%", &CaseErrors::std, true},
      {"stat_max", "%", &CaseErrors::stat_max, true},
      {"stat_min", "%", &CaseErrors::stat_min, true},
      {"max", "%", &CaseErrors::max, true},
      {"min", "%", &CaseErrors::min, true},
      {"uplift", "%", &CaseErrors::uplift, true},
      {"force_rms_filtered", "N", &CaseErrors::force_rms_filtered, false},
      {"probe_rms", "m", &CaseErrors::probe_rms, false},
  };
  std::vector<io::ErrorBarEntry> entries;
  for (std::size_t i = 0; i < at_2dt.size() && i < at_4dt.size(); ++i) {
    if (at_2dt[i].name != at_4dt[i].name) continue;  // not the same part
    for (const Measure& m : measures) {
      const double a = at_2dt[i].errors.*m.field, b = at_4dt[i].errors.*m.field;
      if (std::isnan(a) || std::isnan(b)) continue;
      io::ErrorBarEntry e;
      e.part = at_2dt[i].name;
      e.measure = m.name;
      e.unit = m.unit;
      richardson(a, b, m.signed_difference, e);
      entries.push_back(e);
    }
  }
  return entries;
}

std::vector<io::ErrorBarEntry> worst_estimates(const std::vector<io::ErrorBarEntry>& entries) {
  std::vector<io::ErrorBarEntry> worst;
  for (const io::ErrorBarEntry& e : entries) {
    const auto same = std::find_if(worst.begin(), worst.end(), [&](const io::ErrorBarEntry& w) {
      return w.measure == e.measure;
    });
    if (same == worst.end())
      worst.push_back(e);
    else if (std::abs(e.estimate) > std::abs(same->estimate))
      *same = e;
  }
  for (io::ErrorBarEntry& w : worst) w.part.clear();
  return worst;
}

std::vector<std::optional<DtSiblings>> dt_siblings(const std::vector<StudyRow>& rows) {
  constexpr std::string_view key = "integrator.dt=";
  // The step of a row varied in integrator.dt alone, else NaN.
  const auto step = [&](const StudyRow& r) {
    double dt = std::numeric_limits<double>::quiet_NaN();
    if (!r.completed || r.setting.rfind(key, 0) != 0) return dt;
    const std::string value = r.setting.substr(key.size());
    const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), dt);
    return ec == std::errc() && end == value.data() + value.size() && dt > 0.0
               ? dt
               : std::numeric_limits<double>::quiet_NaN();
  };
  std::vector<std::optional<DtSiblings>> out(rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const double dt = step(rows[i]);
    if (std::isnan(dt)) continue;
    std::optional<std::size_t> at[2];
    for (std::size_t j = 0; j < rows.size(); ++j) {
      if (rows[j].method != rows[i].method) continue;
      const double other = step(rows[j]);
      for (int k = 0; k < 2; ++k)
        if (std::abs(other - (k == 0 ? 2.0 : 4.0) * dt) <= 1e-9 * other) at[k] = j;
    }
    if (at[0] && at[1]) out[i] = DtSiblings{*at[0], *at[1]};
  }
  return out;
}

}  // namespace catena::study
