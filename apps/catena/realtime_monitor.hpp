#pragma once
// `catena run --realtime`: whether a dynamic run kept up with the wall clock, as a
// hardware-in-the-loop rig needs it to. The run keeps up through output interval k (ending
// at simulated time t_k) when the step that reaches t_k ends no later than t_k − t_0 of
// wall time after time stepping began: its lag is (wall − (t_k − t_0)), and an interval
// with a positive lag missed its deadline. Each step's wall time (the step, its output and
// any checkpoint: everything between two accepted steps) gives the mean, the worst and the
// 99th percentile; the same figures of the stepping alone (from the end of the previous
// step's output to the step's acceptance: the method's own cost, which a fixed-cost method
// is judged by), over the steps after the first, show what the output and the start add.
//
// Only rank 0 reads its clock (as the progress lines do); `summary` is broadcast, so every
// rank can record it in the output file.
#include <mpi.h>

#include <cstdio>
#include <utility>
#include <vector>

namespace catena::app {

struct RealtimeSummary {
  long intervals = 0;         // output intervals completed
  long behind = 0;            // of them, ended after their deadline
  double largest_lag = 0.0;   // s, the largest positive lag (0 if none)
  double lag_time = 0.0;      // s, the simulated time at the end of that interval
  double mean_step = 0.0;     // s of wall time per accepted step
  double worst_step = 0.0;    // s
  double worst_time = 0.0;    // s, the simulated time at the end of the worst step
  double percentile99 = 0.0;  // s
  long steps = 0;
  // The stepping alone (without the step's samples, record and checkpoint): the first step
  // apart (it sets up and factors the method's matrices, as a rig's start-up would), the
  // figures of the steps after it.
  double first_stepping = 0.0;  // s
  double mean_stepping = 0.0, worst_stepping = 0.0, worst_stepping_time = 0.0,
         stepping_percentile99 = 0.0;  // s
};

class RealtimeMonitor {
 public:
  // Not collective. Inactive unless `enabled`; then rank 0 measures from now, time stepping
  // starting at simulated time t_start with output every `interval` s.
  RealtimeMonitor(int rank, bool enabled, double t_start, double interval);

  // Not collective. A field sample was written: if it is the start's (no step accepted
  // yet), the steps' clock starts again after it, so that the first step's figures are its
  // own.
  void sampled();
  // Not collective. A step was accepted (before its output).
  void stepped();
  // Not collective. After an accepted step ending at simulated time t, its output written.
  void step(double t);
  // Collective. Rank 0's figures on every rank.
  RealtimeSummary summary(MPI_Comm comm) const;
  // Not collective. The figures as output-file statistics ("realtime_*").
  static std::vector<std::pair<std::string, double>> statistics(const RealtimeSummary& s);
  // Not collective. Rank 0 prints the summary line.
  static void print(int rank, const RealtimeSummary& s, double interval, std::FILE* out = stdout);

  bool enabled() const { return enabled_; }

 private:
  // Not collective (rank 0). The deadline of an interval ending `simulated` s after t_start.
  void deadline(double now, double simulated);

  bool enabled_, active_;
  double t_start_, interval_, start_, last_;
  double stepped_ = -1.0;   // when the current step was accepted (−1: not told)
  long next_interval_ = 1;  // the interval whose deadline comes next (1-based)
  std::vector<double> step_seconds_, stepping_seconds_;
  RealtimeSummary s_;
};

}  // namespace catena::app
