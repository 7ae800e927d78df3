#include "realtime_monitor.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>
#include <utility>

namespace catena::app {

RealtimeMonitor::RealtimeMonitor(int rank, bool enabled, double t_start, double interval)
    : enabled_(enabled),
      active_(enabled && rank == 0),
      t_start_(t_start),
      interval_(interval),
      start_(MPI_Wtime()),
      last_(start_) {}

namespace {

// The mean and the 99th percentile of `seconds` (not empty).
std::pair<double, double> mean_and_p99(const std::vector<double>& seconds) {
  double sum = 0.0;
  for (const double x : seconds) sum += x;
  std::vector<double> sorted = seconds;
  const auto k = static_cast<std::size_t>(std::ceil(0.99 * static_cast<double>(sorted.size()))) - 1;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(k), sorted.end());
  return {sum / static_cast<double>(seconds.size()), sorted[k]};
}

}  // namespace

void RealtimeMonitor::sampled() {
  // Only the start's sample: once the first step is accepted, its own samples are its
  // output, timed with it.
  if (active_ && step_seconds_.empty() && stepped_ < 0.0) last_ = MPI_Wtime();
}

void RealtimeMonitor::stepped() {
  if (active_) stepped_ = MPI_Wtime();
}

void RealtimeMonitor::step(double t) {
  if (!active_) return;
  const double now = MPI_Wtime();
  const double seconds = now - last_;
  const double stepping = stepped_ >= last_ ? stepped_ - last_ : seconds;
  last_ = now;
  stepped_ = -1.0;
  step_seconds_.push_back(seconds);
  if (seconds > s_.worst_step) {
    s_.worst_step = seconds;
    s_.worst_time = t;
  }
  if (step_seconds_.size() == 1) {
    s_.first_stepping = stepping;
  } else {
    stepping_seconds_.push_back(stepping);
    if (stepping > s_.worst_stepping) {
      s_.worst_stepping = stepping;
      s_.worst_stepping_time = t;
    }
  }
  // Every deadline this step reached (a step longer than the interval reaches several);
  // the tolerance keeps a step ending on a sample time from missing it by round-off. With
  // output at every step (interval 0) each step is an interval of its own.
  if (interval_ <= 0.0) {
    deadline(now, t - t_start_);
    return;
  }
  const double tolerance = 1e-9 * interval_;
  while (t - t_start_ >= static_cast<double>(next_interval_) * interval_ - tolerance) {
    deadline(now, static_cast<double>(next_interval_) * interval_);
    ++next_interval_;
  }
}

void RealtimeMonitor::deadline(double now, double simulated) {
  const double lag = (now - start_) - simulated;
  ++s_.intervals;
  if (lag > 0.0) {
    ++s_.behind;
    if (lag > s_.largest_lag) {
      s_.largest_lag = lag;
      s_.lag_time = t_start_ + simulated;
    }
  }
}

RealtimeSummary RealtimeMonitor::summary(MPI_Comm comm) const {
  RealtimeSummary s = s_;
  if (active_ && !step_seconds_.empty()) {
    s.steps = static_cast<long>(step_seconds_.size());
    std::tie(s.mean_step, s.percentile99) = mean_and_p99(step_seconds_);
    if (!stepping_seconds_.empty())
      std::tie(s.mean_stepping, s.stepping_percentile99) = mean_and_p99(stepping_seconds_);
  }
  // Rank 0's figures on every rank: one list of the fields serves both directions.
  double* reals[] = {&s.largest_lag,
                     &s.lag_time,
                     &s.mean_step,
                     &s.worst_step,
                     &s.worst_time,
                     &s.percentile99,
                     &s.first_stepping,
                     &s.mean_stepping,
                     &s.worst_stepping,
                     &s.worst_stepping_time,
                     &s.stepping_percentile99};
  long* counts[] = {&s.intervals, &s.behind, &s.steps};
  std::vector<double> values;
  for (const double* x : reals) values.push_back(*x);
  for (const long* n : counts) values.push_back(static_cast<double>(*n));
  MPI_Bcast(values.data(), static_cast<int>(values.size()), MPI_DOUBLE, 0, comm);
  std::size_t k = 0;
  for (double* x : reals) *x = values[k++];
  for (long* n : counts) *n = static_cast<long>(values[k++]);
  return s;
}

std::vector<std::pair<std::string, double>> RealtimeMonitor::statistics(const RealtimeSummary& s) {
  std::vector<std::pair<std::string, double>> out = {
      {"realtime_intervals", static_cast<double>(s.intervals)},
      {"realtime_intervals_behind", static_cast<double>(s.behind)},
      {"realtime_largest_lag_seconds", s.largest_lag},
      {"realtime_mean_step_seconds", s.mean_step},
      {"realtime_worst_step_seconds", s.worst_step},
      {"realtime_step_seconds_p99", s.percentile99},
      {"realtime_first_stepping_seconds", s.first_stepping}};
  // The steps after the first: none measured, none recorded (zeros would read as figures).
  if (s.steps > 1)
    out.insert(out.end(), {{"realtime_mean_stepping_seconds", s.mean_stepping},
                           {"realtime_worst_stepping_seconds", s.worst_stepping},
                           {"realtime_stepping_seconds_p99", s.stepping_percentile99}});
  return out;
}

void RealtimeMonitor::print(int rank, const RealtimeSummary& s, double interval, std::FILE* out) {
  if (rank != 0) return;
  char each[48];
  if (interval > 0.0)
    std::snprintf(each, sizeof each, "%g s each", interval);
  else
    std::snprintf(each, sizeof each, "one per step");
  if (s.behind == 0)
    std::fprintf(out, "realtime: all %ld output intervals (%s) ended within the wall clock\n",
                 s.intervals, each);
  else
    std::fprintf(out,
                 "realtime: %ld of %ld output intervals (%s) ended behind the wall clock; "
                 "the largest lag %.3g s at t = %g s\n",
                 s.behind, s.intervals, each, s.largest_lag, s.lag_time);
  if (s.steps > 0)
    std::fprintf(out,
                 "realtime: wall time per step (with its output): mean %.3g ms, 99th "
                 "percentile %.3g ms, worst %.3g ms at t = %g s (%.2g x the mean)\n",
                 1e3 * s.mean_step, 1e3 * s.percentile99, 1e3 * s.worst_step, s.worst_time,
                 s.mean_step > 0.0 ? s.worst_step / s.mean_step : 0.0);
  if (s.steps > 1)
    std::fprintf(out,
                 "realtime: the stepping alone (without output and checkpoints), after the "
                 "first step (%.3g ms, with its set-up): mean %.3g ms, 99th percentile %.3g ms, "
                 "worst %.3g ms at t = %g s (%.2g x the mean)\n",
                 1e3 * s.first_stepping, 1e3 * s.mean_stepping, 1e3 * s.stepping_percentile99,
                 1e3 * s.worst_stepping, s.worst_stepping_time,
                 s.mean_stepping > 0.0 ? s.worst_stepping / s.mean_stepping : 0.0);
  std::fflush(out);
}

}  // namespace catena::app
