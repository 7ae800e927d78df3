#include "catena/post/contact_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "catena/core/error.hpp"
#include "catena/post/butterworth.hpp"

namespace catena::post {
namespace {

void check_sampling(double dt, double cutoff_hz) {
  if (!(dt > 0.0) || !std::isfinite(dt) || !(cutoff_hz > 0.0) || !std::isfinite(cutoff_hz)) {
    std::ostringstream os;
    os << "sampling interval " << dt << " s and cutoff " << cutoff_hz
       << " Hz: both must be positive and finite";
    throw InputError({"", 0, "cutoff"}, os.str());
  }
  const double needed_rate = min_sampling_rate_per_cutoff * cutoff_hz;
  if (1.0 / dt < needed_rate * (1.0 - 1e-9)) {
    std::ostringstream os;
    os << "sampling interval " << dt << " s (" << 1.0 / dt << " Hz) is too coarse for a "
       << cutoff_hz << " Hz low-pass: the sampling rate must be at least "
       << min_sampling_rate_per_cutoff << " x the cutoff = " << needed_rate
       << " Hz, i.e. an interval of at most " << 1.0 / needed_rate
       << " s (rerun with a smaller output.interval, or lower the cutoff)";
    throw InputError({"", 0, "dt"}, os.str());
  }
}

void check_section(const EvaluationSection& s) {
  if (!std::isfinite(s.x_start) || !std::isfinite(s.x_end) || !(s.x_end > s.x_start)) {
    std::ostringstream os;
    os << "evaluation section [" << s.x_start << ", " << s.x_end
       << "] m: need finite x_start < x_end";
    throw InputError({"", 0, "section"}, os.str());
  }
}

// A position that differs from a section end by round-off is at that end. The contact
// position stored for the same nominal point is 240.0 or 239.99999999998892 m depending on
// the step sequence (time accumulated over different steps), and the section's sample
// count — and σ with it, by 0.02 % on EN 50318 — must not depend on that. The tolerance is
// far above such round-off (1e-14 relative) and far below the distance between samples.
double end_tolerance(const EvaluationSection& s, double speed, double dt) {
  return std::max(1e-6 * std::abs(speed) * dt,
                  1e-9 * std::max(std::abs(s.x_start), std::abs(s.x_end)));
}

bool in_section(double x, const EvaluationSection& s, double tolerance) {
  return x >= s.x_start - tolerance && x <= s.x_end + tolerance;
}

}  // namespace

std::vector<std::size_t> section_samples(const PantographRecord& pantograph,
                                         const ContactStatisticsOptions& options) {
  check_section(options.section);
  const std::size_t n = pantograph.position.size();
  const double tolerance = end_tolerance(options.section, pantograph.speed, options.dt);
  std::vector<std::size_t> rows;  // the section samples
  for (std::size_t k = 0; k < n; ++k)
    if (in_section(pantograph.position[k], options.section, tolerance)) rows.push_back(k);
  if (rows.empty()) {
    std::ostringstream os;
    os << "pantograph '" << pantograph.name << "' has no sample in the evaluation section ["
       << options.section.x_start << ", " << options.section.x_end << "] m";
    if (n > 0) {
      const auto [lo, hi] =
          std::minmax_element(pantograph.position.begin(), pantograph.position.end());
      os << " (its contact positions range over [" << *lo << ", " << *hi << "] m)";
    } else {
      os << " (the record has no samples)";
    }
    throw InputError({"", 0, "section"}, os.str());
  }
  return rows;
}

ContactStatistics contact_statistics(const PantographRecord& pantograph,
                                     std::span<const RegistrationPoint> supports,
                                     const ContactStatisticsOptions& options) {
  check_sampling(options.dt, options.cutoff_hz);
  check_section(options.section);
  // Filter the whole record, then evaluate inside the section.
  const std::vector<double> filtered =
      butterworth_lowpass_zero_phase(pantograph.force, options.dt, options.cutoff_hz);
  return contact_statistics(pantograph, filtered, supports, options);
}

ContactStatistics contact_statistics(const PantographRecord& pantograph,
                                     std::span<const double> filtered,
                                     std::span<const RegistrationPoint> supports,
                                     const ContactStatisticsOptions& options) {
  check_sampling(options.dt, options.cutoff_hz);
  check_section(options.section);
  const std::size_t n = pantograph.force.size();
  if (filtered.size() != n)
    throw Error("contact statistics of '" + pantograph.name + "': " + std::to_string(n) +
                " force samples but " + std::to_string(filtered.size()) + " filtered ones");
  if (pantograph.position.size() != n)
    throw Error("contact statistics of '" + pantograph.name + "': " + std::to_string(n) +
                " force samples but " + std::to_string(pantograph.position.size()) + " positions");
  for (const RegistrationPoint& p : supports)
    if (p.z.size() != n)
      throw Error("contact statistics of '" + pantograph.name + "': " + std::to_string(n) +
                  " force samples but a registration point has " + std::to_string(p.z.size()));

  const std::vector<std::size_t> rows = section_samples(pantograph, options);
  const double tolerance = end_tolerance(options.section, pantograph.speed, options.dt);

  ContactStatistics s;
  s.n_samples = rows.size();
  double sum = 0.0;
  s.max = filtered[rows.front()];
  s.min = filtered[rows.front()];
  std::size_t n_lost = 0;
  for (std::size_t k : rows) {
    sum += filtered[k];
    s.max = std::max(s.max, filtered[k]);
    s.min = std::min(s.min, filtered[k]);
    if (pantograph.force[k] <= 0.0) ++n_lost;
  }
  const double count = static_cast<double>(rows.size());
  s.mean = sum / count;
  double squares = 0.0;  // two passes: no cancellation for a large mean and small σ
  for (std::size_t k : rows) squares += (filtered[k] - s.mean) * (filtered[k] - s.mean);
  s.standard_deviation = std::sqrt(squares / count);
  s.statistical_max = s.mean + 3.0 * s.standard_deviation;
  s.statistical_min = s.mean - 3.0 * s.standard_deviation;
  s.contact_loss_percent = 100.0 * static_cast<double>(n_lost) / count;

  // Each support's window: the pantograph between the neighbouring registration points.
  // The support peaks 0.1-0.2 m after the head has passed it, so the section's own
  // samples would cut the peak at its last support (57.24 instead of 57.44 mm at 300 km/h
  // on the EN 50318 line).
  std::vector<double> support_x;
  for (const RegistrationPoint& p : supports) support_x.push_back(p.reference_x);
  std::sort(support_x.begin(), support_x.end());
  for (const RegistrationPoint& p : supports) {
    if (!in_section(p.reference_x, options.section, tolerance)) continue;
    ++s.n_supports;
    const auto at = std::equal_range(support_x.begin(), support_x.end(), p.reference_x);
    const double from = at.first == support_x.begin() ? -HUGE_VAL : *(at.first - 1);
    const double to = at.second == support_x.end() ? HUGE_VAL : *at.second;
    for (std::size_t k = 0; k < n; ++k) {
      if (pantograph.position[k] < from || pantograph.position[k] > to) continue;
      const double uplift = p.z[k] - p.z[0];
      if (!s.max_uplift_at_support || uplift > *s.max_uplift_at_support)
        s.max_uplift_at_support = uplift;
    }
  }
  return s;
}

}  // namespace catena::post
