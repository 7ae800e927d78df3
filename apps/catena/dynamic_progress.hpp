#pragma once
// Progress of a dynamic run, so that a long run never looks hung: rank 0 prints a line to
// standard output every `interval` seconds of wall time, e.g.
//
//   progress: t = 0.512 s of 2.5 s (20.5 %), 1024 steps (3 rejected), 2.4 Newton
//   iterations/step, 41.2 steps/s, wall 24.8 s, ETA 1 min 37 s
//
// (one line). Rates and the ETA are of this process (a restarted run counts from its
// checkpoint). Only rank 0 reads its clock and prints, and no other rank depends on what it
// decides, so the ranks' clocks never need to agree (no collective call here).
#include <cstdio>

namespace catena::app {

class DynamicProgress {
 public:
  // Not collective. `interval` s of wall time between lines: 0 prints after every step,
  // a negative value never. `t_start`: the simulated time this run starts from.
  DynamicProgress(int rank, double t_start, double t_end, double interval, std::FILE* out = stdout);

  // Not collective. After an accepted step ending at t.
  void step(double t, int newton_iterations, int rejected);

 private:
  void print(double t, double now);

  bool active_;
  double t_start_, t_end_, interval_;
  std::FILE* out_;
  double wall_start_, last_line_;
  long steps_ = 0, rejected_ = 0, newton_iterations_ = 0;
};

}  // namespace catena::app
