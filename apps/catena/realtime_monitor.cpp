#include "realtime_monitor.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace catena::app {

RealtimeMonitor::RealtimeMonitor(int rank, bool enabled, double t_start, double interval)
    : enabled_(enabled),
      active_(enabled && rank == 0),
      t_start_(t_start),
      interval_(interval),
      start_(MPI_Wtime()),
      last_(start_) {}

void RealtimeMonitor::step(double t) {
  if (!active_) return;
  const double now = MPI_Wtime();
  const double seconds = now - last_;
  last_ = now;
  step_seconds_.push_back(seconds);
  if (seconds > s_.worst_step) {
    s_.worst_step = seconds;
    s_.worst_time = t;
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
    double sum = 0.0;
    for (const double x : step_seconds_) sum += x;
    s.mean_step = sum / static_cast<double>(s.steps);
    std::vector<double> sorted = step_seconds_;
    const auto k =
        static_cast<std::size_t>(std::ceil(0.99 * static_cast<double>(sorted.size()))) - 1;
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(k), sorted.end());
    s.percentile99 = sorted[k];
  }
  double values[9] = {static_cast<double>(s.intervals),
                      static_cast<double>(s.behind),
                      s.largest_lag,
                      s.lag_time,
                      s.mean_step,
                      s.worst_step,
                      s.worst_time,
                      s.percentile99,
                      static_cast<double>(s.steps)};
  MPI_Bcast(values, 9, MPI_DOUBLE, 0, comm);
  s = {static_cast<long>(values[0]),
       static_cast<long>(values[1]),
       values[2],
       values[3],
       values[4],
       values[5],
       values[6],
       values[7],
       static_cast<long>(values[8])};
  return s;
}

std::vector<std::pair<std::string, double>> RealtimeMonitor::statistics(const RealtimeSummary& s) {
  return {{"realtime_intervals", static_cast<double>(s.intervals)},
          {"realtime_intervals_behind", static_cast<double>(s.behind)},
          {"realtime_largest_lag_seconds", s.largest_lag},
          {"realtime_mean_step_seconds", s.mean_step},
          {"realtime_worst_step_seconds", s.worst_step},
          {"realtime_step_seconds_p99", s.percentile99}};
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
  std::fflush(out);
}

}  // namespace catena::app
