#pragma once
// Testing hooks of dynamic runs, read from the environment (docs/output.md, "Testing
// hooks"): deterministic stop, crash and checkpoint points for the restart tests, which
// must not depend on the wall clock. Unset (the normal case), they do nothing.
//   CATENA_STOP_AFTER_STEPS=N        after N accepted steps of this process, behave as if
//                                    SIGTERM had arrived (checkpoint, "interrupted", 143);
//   CATENA_KILL_AFTER_STEPS=N        after N accepted steps, SIGKILL every rank (a crash:
//                                    the output is left open, the last checkpoint stays);
//   CATENA_CHECKPOINT_EVERY_STEPS=N  a checkpoint after every N-th accepted step, as the
//                                    wall clock (output.checkpoint_wall_seconds) would.
namespace catena::app {

class TestHooks {
 public:
  // Not collective (every rank reads the same environment under mpirun). Throws
  // catena::InputError naming the variable if a value is not a positive integer.
  static TestHooks from_environment();

  // Not collective. Counts an accepted step; true if a checkpoint is due after it.
  bool checkpoint_due();
  // Not collective. After the step's output and checkpoint: stops or kills if due.
  void after_step() const;

 private:
  long steps_ = 0;
  long stop_after_ = 0, kill_after_ = 0, checkpoint_every_ = 0;
};

}  // namespace catena::app
