#include "catena/post/run_difference.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "catena/core/error.hpp"
#include "catena/post/butterworth.hpp"

namespace catena::post {

std::vector<double> resample_linear(std::span<const double> times, std::span<const double> values,
                                    std::span<const double> at) {
  if (times.size() != values.size())
    throw Error("resample: " + std::to_string(times.size()) + " times but " +
                std::to_string(values.size()) + " values");
  std::vector<double> out;
  out.reserve(at.size());
  if (at.empty()) return out;
  if (times.empty()) throw InputError({"", 0, "time"}, "the run has no samples to resample");
  const double reach = 1e-9 * std::max(1.0, std::abs(times.back() - times.front()));
  for (double t : at) {
    if (t < times.front() - reach || t > times.back() + reach) {
      std::ostringstream os;
      os << "the run's samples cover [" << times.front() << ", " << times.back()
         << "] s, not t = " << t << " s (did it stop early?)";
      throw InputError({"", 0, "time"}, os.str());
    }
    const auto upper = std::upper_bound(times.begin(), times.end(), t);
    if (upper == times.begin()) {
      out.push_back(values.front());
    } else if (upper == times.end()) {
      out.push_back(values.back());
    } else {
      const std::size_t k = static_cast<std::size_t>(upper - times.begin());
      const double w = (t - times[k - 1]) / (times[k] - times[k - 1]);
      out.push_back((1.0 - w) * values[k - 1] + w * values[k]);
    }
  }
  return out;
}

ForceDifference force_difference(const PantographRecord& run, const PantographRecord& reference,
                                 const ContactStatisticsOptions& options) {
  if (run.force.size() != reference.force.size() ||
      reference.position.size() != reference.force.size())
    throw Error("force difference of '" + reference.name +
                "': " + std::to_string(run.force.size()) + " samples against the reference's " +
                std::to_string(reference.force.size()));
  const std::vector<std::size_t> rows = section_samples(reference, options);
  const std::vector<double> run_filtered =
      butterworth_lowpass_zero_phase(run.force, options.dt, options.cutoff_hz);
  const std::vector<double> reference_filtered =
      butterworth_lowpass_zero_phase(reference.force, options.dt, options.cutoff_hz);
  ForceDifference d;
  d.n_samples = rows.size();
  double raw_squares = 0.0, filtered_squares = 0.0;
  for (std::size_t k : rows) {
    const double raw = run.force[k] - reference.force[k];
    const double filtered = run_filtered[k] - reference_filtered[k];
    raw_squares += raw * raw;
    filtered_squares += filtered * filtered;
    d.max_raw = std::max(d.max_raw, std::abs(raw));
    d.max_filtered = std::max(d.max_filtered, std::abs(filtered));
  }
  const double count = static_cast<double>(rows.size());
  d.rms_raw = std::sqrt(raw_squares / count);
  d.rms_filtered = std::sqrt(filtered_squares / count);
  return d;
}

TrackDifference track_difference(std::span<const double> run, std::span<const double> reference) {
  if (run.size() != reference.size() || run.size() % 3 != 0)
    throw Error("track difference: " + std::to_string(run.size()) + " against " +
                std::to_string(reference.size()) + " coordinates (n x 3 each)");
  TrackDifference d;
  const std::size_t n = run.size() / 3;
  if (n == 0) return d;
  double squares = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    double distance2 = 0.0;
    for (std::size_t c = 0; c < 3; ++c) {
      const double e = run[3 * k + c] - reference[3 * k + c];
      distance2 += e * e;
    }
    squares += distance2;
    d.max = std::max(d.max, std::sqrt(distance2));
  }
  d.rms = std::sqrt(squares / static_cast<double>(n));
  return d;
}

double relative_error(double value, double reference, double floor) {
  return (value - reference) / std::max(std::abs(reference), floor);
}

}  // namespace catena::post
