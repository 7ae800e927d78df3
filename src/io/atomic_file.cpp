#include "catena/io/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <system_error>

#include "catena/core/error.hpp"
#include "catena/io/output_error.hpp"

namespace catena::io {
namespace {

[[noreturn]] void throw_system_error(std::string_view call, const std::filesystem::path& path,
                                     int error_number) {
  throw Error(std::string(call) + " failed for '" + path.string() +
              "': " + std::strerror(error_number));
}

// Closes a POSIX descriptor on scope exit; close() failures after a successful fsync are
// not data loss, and this may run while an exception unwinds, so the status is dropped.
class FileDescriptor {
 public:
  explicit FileDescriptor(int fd) : fd_(fd) {}
  ~FileDescriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  FileDescriptor(const FileDescriptor&) = delete;
  FileDescriptor& operator=(const FileDescriptor&) = delete;
  int get() const { return fd_; }
  // Closes now and reports failure (NFS may report a deferred write error only here).
  int close_now() {
    const int status = ::close(fd_);
    fd_ = -1;
    return status;
  }

 private:
  int fd_;
};

}  // namespace

std::filesystem::path temporary_sibling(const std::filesystem::path& target, pid_t pid) {
  std::filesystem::path temporary = target;
  temporary += ".tmp-" + std::to_string(pid);
  return temporary;
}

void write_file_durably(const std::filesystem::path& path, std::string_view contents) {
  FileDescriptor file(::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666));
  if (file.get() < 0) throw_system_error("open", path, errno);
  std::size_t n_written = 0;
  while (n_written < contents.size()) {
    const ssize_t n = ::write(file.get(), contents.data() + n_written, contents.size() - n_written);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw_system_error("write", path, errno);
    }
    n_written += static_cast<std::size_t>(n);
  }
  if (::fsync(file.get()) != 0) throw_system_error("fsync", path, errno);
  if (file.close_now() != 0) throw_system_error("close", path, errno);
}

void fsync_path(const std::filesystem::path& path) {
  // O_RDONLY suffices: fsync flushes the inode's dirty pages whatever the open mode, and
  // it is the only way to open a directory.
  FileDescriptor file(::open(path.c_str(), O_RDONLY | O_CLOEXEC));
  if (file.get() < 0) throw_system_error("open", path, errno);
  if (::fsync(file.get()) != 0) throw_system_error("fsync", path, errno);
}

void rename_into_place(const std::filesystem::path& from, const std::filesystem::path& to) {
  if (std::rename(from.c_str(), to.c_str()) != 0)
    throw Error("rename('" + from.string() + "', '" + to.string() +
                "') failed: " + std::strerror(errno));
}

TemporaryFile::~TemporaryFile() {
  if (released_) return;
  std::error_code ignored;
  if (std::filesystem::is_regular_file(std::filesystem::symlink_status(path_, ignored)))
    std::filesystem::remove(path_, ignored);
}

void publish_with_xdmf(TemporaryFile& hdf5, const std::filesystem::path& hdf5_path,
                       TemporaryFile& xdmf, const std::filesystem::path& xdmf_path) {
  rename_into_place(hdf5.path(), hdf5_path);
  hdf5.release();
  try {
    rename_into_place(xdmf.path(), xdmf_path);
  } catch (const Error& error) {
    throw Error(std::string(error.what()) + "; the HDF5 file was written, its XDMF was not");
  }
  xdmf.release();
  // The renames are directory entries: durable once the directory is synced.
  fsync_path(hdf5_path.has_parent_path() ? hdf5_path.parent_path() : std::filesystem::path("."));
}

void write_file_atomically(const std::filesystem::path& path, std::string_view contents) {
  try {
    TemporaryFile temporary(temporary_sibling(path, getpid()));
    write_file_durably(temporary.path(), contents);
    rename_into_place(temporary.path(), path);
    temporary.release();
  } catch (const OutputError&) {
    throw;
  } catch (const Error& e) {
    // An unwritable place (`export -o /proc/x`) is the output's failure (exit 4), not
    // Catena's.
    throw OutputError("cannot write '" + path.string() + "': " + e.what());
  }
}

}  // namespace catena::io
