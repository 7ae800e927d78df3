#include "stop_signal.hpp"

#include <csignal>
#include <cstdlib>
#include <functional>
#include <utility>

namespace catena::app {
namespace {

volatile std::sig_atomic_t received = 0;
using Handler = void (*)(int);
Handler previous_term = SIG_DFL, previous_int = SIG_DFL;
std::function<bool()> extra_poll;  // ExtraStop's, while one is alive
int depth = 0;                     // StopSignal objects alive

extern "C" void on_stop_signal(int signal) {
  if (received != 0) std::_Exit(128 + signal);  // asked twice: stop now
  received = signal;
}

}  // namespace

StopSignal::StopSignal() {
  // Nested (a run inside `--error-bar-ranks`' handlers): the outer one's handlers and any
  // signal already received stay.
  if (depth++ > 0) return;
  received = 0;
  previous_term = std::signal(SIGTERM, on_stop_signal);
  previous_int = std::signal(SIGINT, on_stop_signal);
}

StopSignal::~StopSignal() {
  if (--depth > 0) return;
  std::signal(SIGTERM, previous_term);
  std::signal(SIGINT, previous_int);
}

bool StopSignal::requested() { return received != 0 || (extra_poll && extra_poll()); }
int StopSignal::signal_number() { return received; }
void StopSignal::request(int signal) { received = signal; }

ExtraStop::ExtraStop(std::function<bool()> poll) { extra_poll = std::move(poll); }
ExtraStop::~ExtraStop() { extra_poll = nullptr; }

}  // namespace catena::app
