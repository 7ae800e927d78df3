#pragma once
// SIGTERM and SIGINT (what batch schedulers and Ctrl-C send) during a dynamic run: the
// handler only sets a flag; the step-control driver polls it between steps, all ranks stop
// at the same step, and the run ends with a checkpoint and a complete, readable output
// file whose status says "interrupted". A second signal exits at once.
#include <functional>

namespace catena::app {

// Installs the handlers for the lifetime of the object and restores the previous ones.
class StopSignal {
 public:
  StopSignal();
  ~StopSignal();
  StopSignal(const StopSignal&) = delete;
  StopSignal& operator=(const StopSignal&) = delete;
  static bool requested();
  static int signal_number();  // the signal received (0: none)
  // As if `signal` had arrived (a testing hook, test_hooks.hpp).
  static void request(int signal);
};

// While one is alive, StopSignal::requested() is also true once `poll` returns true: a stop
// asked for by another part of the job, not by a signal (signal_number() stays 0). The
// comparison runs of `catena run --error-bar-ranks` stop so when the run they serve has
// failed (error_bar.cpp). Polled between steps: keep it cheap.
class ExtraStop {
 public:
  explicit ExtraStop(std::function<bool()> poll);
  ~ExtraStop();
  ExtraStop(const ExtraStop&) = delete;
  ExtraStop& operator=(const ExtraStop&) = delete;
};

}  // namespace catena::app
