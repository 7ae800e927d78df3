#pragma once
// Ranks that outlive their launcher. When mpirun is killed (kill -9, a node agent's
// OOM kill), Open MPI leaves its ranks running, unseen and holding the output. A rank
// launched by mpirun (it is mpirun's child on mpirun's node) watches its parent: when the
// parent is gone (the rank was re-parented) it stops as if SIGTERM had arrived — the
// dynamics finish their step, write a checkpoint and close the output as "interrupted",
// every other phase ends at once — and, if that has not ended the process within
// `grace_seconds`, exits without further writes. SIGPIPE is ignored from then on: the
// launcher's end of stdout and stderr is gone.
//
// Not started for a rank without a launcher (`catena run` alone, or under nohup): its
// parent is a shell that may legitimately go away.
#include <condition_variable>
#include <mutex>
#include <thread>

namespace catena::app {

class LauncherWatch {
 public:
  explicit LauncherWatch(double grace_seconds = 60.0);
  ~LauncherWatch();  // stops the watching thread
  LauncherWatch(const LauncherWatch&) = delete;
  LauncherWatch& operator=(const LauncherWatch&) = delete;

 private:
  void watch(long parent, double grace_seconds);
  std::mutex mutex_;
  std::condition_variable wake_;
  bool done_ = false;
  std::thread thread_;
};

}  // namespace catena::app
