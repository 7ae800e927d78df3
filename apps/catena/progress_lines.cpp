#include "progress_lines.hpp"

#include <mpi.h>

#include <cmath>
#include <memory>
#include <string>

namespace catena::app {

ProgressPacer::ProgressPacer(int rank, double interval)
    : active_(rank == 0 && interval >= 0.0),
      interval_(interval),
      start_(MPI_Wtime()),
      last_(start_) {}

bool ProgressPacer::due() {
  if (!active_) return false;
  const double now = MPI_Wtime();
  if (now - last_ < interval_) return false;
  last_ = now;
  return true;
}

double ProgressPacer::elapsed() const { return MPI_Wtime() - start_; }

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

DynamicProgress::DynamicProgress(int rank, double t_start, double t_end, double interval,
                                 std::FILE* out)
    : pacer_(rank, interval), t_start_(t_start), t_end_(t_end), out_(out) {}

void DynamicProgress::step(double t, int newton_iterations, int rejected) {
  ++steps_;
  rejected_ += rejected;
  newton_iterations_ += newton_iterations;
  if (!pacer_.due()) return;
  const double wall = pacer_.elapsed();
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

std::function<void(const solvers::StaticProgress&)> static_progress_lines(int rank, double interval,
                                                                          std::FILE* out) {
  auto pacer = std::make_shared<ProgressPacer>(rank, interval);
  return [pacer, out](const solvers::StaticProgress& p) {
    if (!pacer->due()) return;
    std::fprintf(out,
                 "progress: statics at %s, %d load steps (%d rejected), %d Newton iterations, "
                 "wall %s\n",
                 p.where.c_str(), p.n_load_steps, p.n_rejected_steps, p.n_newton_iterations,
                 duration_text(pacer->elapsed()).c_str());
    std::fflush(out);
  };
}

}  // namespace catena::app
