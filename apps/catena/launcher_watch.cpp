#include "launcher_watch.hpp"

#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>

namespace catena::app {
namespace {

// Open MPI's launcher sets these in every rank it starts (a singleton run has none).
bool launched_by_mpirun() {
  return std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr &&
         std::getenv("OMPI_COMM_WORLD_LOCAL_RANK") != nullptr;
}

}  // namespace

LauncherWatch::LauncherWatch(double grace_seconds) {
  if (!launched_by_mpirun()) return;
  const long parent = static_cast<long>(::getppid());
  if (parent <= 1) return;  // already orphaned at start: nothing to tell apart
  thread_ = std::thread([this, parent, grace_seconds] { watch(parent, grace_seconds); });
}

LauncherWatch::~LauncherWatch() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    done_ = true;
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void LauncherWatch::watch(long parent, double grace_seconds) {
  using namespace std::chrono_literals;
  std::unique_lock<std::mutex> lock(mutex_);
  // A getppid() every half second costs nothing next to a time step.
  while (!wake_.wait_for(lock, 500ms, [this] { return done_; })) {
    if (static_cast<long>(::getppid()) == parent) continue;
    std::signal(SIGPIPE, SIG_IGN);
    std::raise(SIGTERM);  // dynamics: a clean stop; elsewhere the default action ends us
    const auto give_up =
        std::chrono::steady_clock::now() + std::chrono::duration<double>(grace_seconds);
    if (!wake_.wait_until(lock, give_up, [this] { return done_; })) std::_Exit(128 + SIGTERM);
    return;
  }
}

}  // namespace catena::app
