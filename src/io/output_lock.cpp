#include "catena/io/output_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "catena/core/error.hpp"
#include "catena/core/mpi_comm.hpp"

namespace catena::io {
namespace {

std::string host_name() {
  char name[256] = {};
  if (gethostname(name, sizeof name - 1) != 0) return "?";
  return name;
}

std::string holder_of(const std::string& path) {
  std::ifstream in(path);
  std::string pid, host;
  in >> pid >> host;
  if (pid.empty()) return "another process";
  return "process " + pid + (host.empty() ? "" : " on " + host);
}

// Not collective. Locks `path`, retrying if the file was removed and recreated by a
// finishing holder between our open and our flock (then our descriptor names a file no
// longer at `path`). Returns the descriptor, or -1 with `why` set.
int acquire(const std::string& path, std::string& why, bool& held_by_other) {
  held_by_other = false;
  for (int attempt = 0; attempt < 10; ++attempt) {
    const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0666);
    if (fd < 0) {
      why = "cannot create the lock file '" + path + "': " + std::strerror(errno);
      return -1;
    }
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const int error = errno;
      ::close(fd);
      if (error == EWOULDBLOCK) {
        held_by_other = true;
        why = holder_of(path);
      } else {
        why = "cannot lock '" + path + "': " + std::strerror(error);
      }
      return -1;
    }
    struct stat open_file {
    }, named_file{};
    if (::fstat(fd, &open_file) == 0 && ::stat(path.c_str(), &named_file) == 0 &&
        open_file.st_ino == named_file.st_ino && open_file.st_dev == named_file.st_dev) {
      const std::string owner = std::to_string(::getpid()) + " " + host_name() + "\n";
      if (::ftruncate(fd, 0) == 0 && ::write(fd, owner.data(), owner.size()) < 0) {
        // The owner text only improves another run's message; the lock is what counts.
      }
      return fd;
    }
    ::close(fd);  // removed or replaced under us: try again with the file now there
  }
  why = "the lock file '" + path + "' keeps being replaced";
  return -1;
}

}  // namespace

OutputLock::OutputLock(MPI_Comm comm, const std::string& output_path)
    : path_(lock_path(output_path)) {
  std::string why;
  int code = 0;  // 0 locked, 1 held by another run, 2 cannot lock
  if (mpi_rank(comm) == 0) {
    bool held = false;
    fd_ = acquire(path_, why, held);
    code = fd_ >= 0 ? 0 : (held ? 1 : 2);
  }
  MPI_Bcast(&code, 1, MPI_INT, 0, comm);
  if (code == 0) return;
  broadcast_string(comm, why, 0);
  if (code == 1)
    throw InputError({output_path, 0, "output.file"},
                     "another run is writing this output (" + why + " holds " + path_ +
                         "); give this run another output name (-o) or wait for that one");
  throw InputError({output_path, 0, "output.file"},
                   why + "; the output's directory must exist and be writable");
}

OutputLock::~OutputLock() {
  if (fd_ < 0) return;
  // Remove before unlocking: a run waiting to lock then finds the name gone or new, never
  // a removed file it could lock alongside a third run (acquire() checks the inode).
  ::unlink(path_.c_str());
  ::close(fd_);
}

}  // namespace catena::io
