#pragma once
// The acceptance ranges of the EN 50318 reference case: the contact-force statistics a
// simulation of the reference catenary and pantograph must give at 250 and 300 km/h to be
// validated (EN 50318:2002, as reproduced by Wang et al., IEEE Trans. Power Delivery 31(4),
// 2016, Table III; docs/validation.md). `catena stats` checks a run against them when the
// scene declares itself the reference case (catenary.acceptance: en50318).
//
// The ranges are closed intervals and the statistics are compared unrounded: σ = 31.004 N
// fails the 250 km/h range 26 – 31 N. Pure functions: no files, no MPI.
#include <optional>
#include <string>
#include <vector>

#include "catena/post/contact_statistics.hpp"

namespace catena::post {

// One statistic's range and the run's value.
struct AcceptanceCheck {
  std::string statistic;  // the key of `catena stats --json`: mean, std, ..., max_uplift_at_support
  std::string label;      // as EN 50318 names it, e.g. "statistical maximum F_m + 3σ"
  std::string unit;       // of low, high and value: "N", "mm" or "%"
  double low = 0.0, high = 0.0;
  std::optional<double> value;  // none: the run has no such statistic (no support in the section)
  bool pass = false;            // value present and low ≤ value ≤ high
};

// The speeds EN 50318 gives ranges for, km/h.
inline constexpr double en50318_speeds_kmh[] = {250.0, 300.0};

// Not collective. The eight checks of `statistics` at `speed_kmh` (its uplift in mm), or none
// when the speed is not one of en50318_speeds_kmh (within 0.05 km/h: a scene's speed given
// in m/s and printed rounded still matches).
std::optional<std::vector<AcceptanceCheck>> check_en50318(const ContactStatistics& statistics,
                                                          double speed_kmh);

}  // namespace catena::post
