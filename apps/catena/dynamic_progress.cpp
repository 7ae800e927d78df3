#include "dynamic_progress.hpp"

#include <mpi.h>

#include <cmath>
#include <string>

namespace catena::app {
namespace {

// "0.4 s", "37 s", "4 min 05 s", "2 h 13 min".
std::string duration_text(double seconds) {
  char text[48];
  const long s = std::lround(seconds);
  if (seconds < 9.95)
    std::snprintf(text, sizeof text, "%.1f s", seconds);
  else if (s < 120)
    std::snprintf(text, sizeof text, "%ld s", s);
  else if (s < 7200)
    std::snprintf(text, sizeof text, "%ld min %02ld s", s / 60, s % 60);
  else
    std::snprintf(text, sizeof text, "%ld h %02ld min", s / 3600, s / 60 % 60);
  return text;
}

}  // namespace

DynamicProgress::DynamicProgress(int rank, double t_start, double t_end, double interval,
                                 std::FILE* out)
    : active_(rank == 0 && interval >= 0.0),
      t_start_(t_start),
      t_end_(t_end),
      interval_(interval),
      out_(out),
      wall_start_(MPI_Wtime()),
      last_line_(wall_start_) {}

void DynamicProgress::step(double t, int newton_iterations, int rejected) {
  if (!active_) return;
  ++steps_;
  rejected_ += rejected;
  newton_iterations_ += newton_iterations;
  const double now = MPI_Wtime();
  if (now - last_line_ < interval_) return;
  last_line_ = now;
  print(t, now);
}

void DynamicProgress::print(double t, double now) {
  const double wall = now - wall_start_;
  const double done = t - t_start_;
  const double percent = t_end_ > 0.0 ? 100.0 * t / t_end_ : 100.0;
  const double rate = wall > 0.0 ? static_cast<double>(steps_) / wall : 0.0;  // steps/s
  std::string eta = "unknown";
  if (done > 0.0) eta = duration_text(wall * (t_end_ - t) / done);
  std::fprintf(out_,
               "progress: t = %.6g s of %g s (%.1f %%), %ld steps (%ld rejected), %.1f Newton "
               "iterations/step, %.*f steps/s, wall %s, ETA %s\n",
               t, t_end_, percent, steps_, rejected_,
               static_cast<double>(newton_iterations_) / static_cast<double>(steps_),
               rate < 100.0 ? 1 : 0, rate, duration_text(wall).c_str(), eta.c_str());
  std::fflush(out_);
}

}  // namespace catena::app
