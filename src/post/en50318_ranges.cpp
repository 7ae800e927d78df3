#include "catena/post/en50318_ranges.hpp"

#include <cmath>

namespace catena::post {
namespace {

struct Range {
  double low, high;
};

// EN 50318:2002 Table (as reproduced by Wang et al. 2016, Table III): per statistic, the
// range at 250 km/h and at 300 km/h.
struct RangeRow {
  const char* statistic;
  const char* label;
  const char* unit;
  Range at_250, at_300;
};

constexpr RangeRow ranges[] = {
    {"mean", "mean F_m", "N", {110, 120}, {110, 120}},
    {"std", "standard deviation σ", "N", {26, 31}, {32, 40}},
    {"stat_max", "statistical maximum F_m + 3σ", "N", {190, 210}, {210, 230}},
    {"stat_min", "statistical minimum F_m − 3σ", "N", {20, 40}, {-5, 20}},
    {"max", "actual maximum", "N", {175, 210}, {190, 225}},
    {"min", "actual minimum", "N", {50, 75}, {30, 55}},
    {"max_uplift_at_support", "maximum uplift at support", "mm", {48, 55}, {55, 65}},
    {"contact_loss_percent", "loss of contact", "%", {0, 0}, {0, 0}},
};

constexpr double speed_tolerance_kmh = 0.05;

std::optional<double> value_of(const ContactStatistics& s, const std::string& statistic) {
  if (statistic == "mean") return s.mean;
  if (statistic == "std") return s.standard_deviation;
  if (statistic == "stat_max") return s.statistical_max;
  if (statistic == "stat_min") return s.statistical_min;
  if (statistic == "max") return s.max;
  if (statistic == "min") return s.min;
  if (statistic == "contact_loss_percent") return s.contact_loss_percent;
  if (statistic == "max_uplift_at_support" && s.max_uplift_at_support)
    return 1e3 * *s.max_uplift_at_support;  // m -> mm
  return std::nullopt;
}

}  // namespace

std::optional<std::vector<AcceptanceCheck>> check_en50318(const ContactStatistics& statistics,
                                                          double speed_kmh) {
  const bool at_250 = std::abs(speed_kmh - en50318_speeds_kmh[0]) <= speed_tolerance_kmh;
  const bool at_300 = std::abs(speed_kmh - en50318_speeds_kmh[1]) <= speed_tolerance_kmh;
  if (!at_250 && !at_300) return std::nullopt;
  std::vector<AcceptanceCheck> checks;
  for (const RangeRow& row : ranges) {
    AcceptanceCheck c;
    c.statistic = row.statistic;
    c.label = row.label;
    c.unit = row.unit;
    const Range r = at_250 ? row.at_250 : row.at_300;
    c.low = r.low;
    c.high = r.high;
    c.value = value_of(statistics, c.statistic);
    c.pass = c.value && *c.value >= c.low && *c.value <= c.high;
    checks.push_back(std::move(c));
  }
  return checks;
}

}  // namespace catena::post
