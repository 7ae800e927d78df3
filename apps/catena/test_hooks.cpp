#include "test_hooks.hpp"

#include <csignal>
#include <cstdlib>
#include <string>

#include "catena/core/error.hpp"
#include "stop_signal.hpp"

namespace catena::app {
namespace {

long positive_variable(const char* name) {
  const char* text = std::getenv(name);
  if (!text || !*text) return 0;
  char* end = nullptr;
  const long value = std::strtol(text, &end, 10);
  if (*end != '\0' || value <= 0)
    throw InputError({"", 0, name}, std::string("environment variable ") + name + " = '" + text +
                                        "'; accepted: a positive integer (steps)");
  return value;
}

}  // namespace

TestHooks TestHooks::from_environment() {
  TestHooks h;
  h.stop_after_ = positive_variable("CATENA_STOP_AFTER_STEPS");
  h.kill_after_ = positive_variable("CATENA_KILL_AFTER_STEPS");
  h.checkpoint_every_ = positive_variable("CATENA_CHECKPOINT_EVERY_STEPS");
  return h;
}

bool TestHooks::checkpoint_due() {
  ++steps_;
  return checkpoint_every_ > 0 && steps_ % checkpoint_every_ == 0;
}

void TestHooks::after_step() const {
  if (kill_after_ > 0 && steps_ == kill_after_) std::raise(SIGKILL);
  if (stop_after_ > 0 && steps_ == stop_after_) StopSignal::request(SIGTERM);
}

}  // namespace catena::app
