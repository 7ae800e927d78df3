#pragma once
// Progress lines, so that a long phase never looks hung: rank 0 prints a line to standard
// output every `interval` seconds of wall time (0: at every step; negative: never).
//   dynamics:  progress: t = 0.512 s of 2.5 s (20.5 %), 1024 steps (3 rejected), 2.4 Newton
//              iterations/step, 41.2 steps/s, wall 24.8 s, ETA 1 min 37 s
//   statics:   progress: statics at load factor 0.75, 9 load steps (2 rejected), 41 Newton
//              iterations, wall 12.0 s
// (one line each). Only rank 0 reads its clock and prints, and no other rank depends on
// what it decides, so the ranks' clocks never need to agree (no collective call here).
#include <cstdio>
#include <functional>

#include "catena/solvers/statics/static_solver.hpp"

namespace catena::app {

// When the next line is due. Not collective.
class ProgressPacer {
 public:
  ProgressPacer(int rank, double interval);
  // True (on rank 0 only) when `interval` s have passed since the last line or the start.
  bool due();
  double elapsed() const;  // s of wall time since construction

 private:
  bool active_;
  double interval_, start_, last_;
};

// Not collective. "0.4 s", "37 s", "4 min 05 s", "2 h 13 min".
std::string duration_text(double seconds);

class DynamicProgress {
 public:
  // Not collective. `t_start`: the simulated time this run starts from (a restart: its
  // checkpoint's), so rates and the ETA are of this process.
  DynamicProgress(int rank, double t_start, double t_end, double interval, std::FILE* out = stdout);

  // Not collective. After an accepted step ending at t.
  void step(double t, int newton_iterations, int rejected);

 private:
  ProgressPacer pacer_;
  double t_start_, t_end_;
  std::FILE* out_;
  long steps_ = 0, rejected_ = 0, newton_iterations_ = 0;
};

// Not collective. A StaticSolver::on_progress callback printing the static solve's lines.
std::function<void(const solvers::StaticProgress&)> static_progress_lines(int rank, double interval,
                                                                          std::FILE* out = stdout);

}  // namespace catena::app
