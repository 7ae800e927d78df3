#pragma once
// Replacing an output file atomically: write a temporary sibling, fsync it, rename(2) it
// over the target, fsync the directory. rename within one directory is atomic on POSIX
// file systems, so a reader (or a crash) sees either the old complete file or the new
// complete one, never a half-written file. Not collective; the caller decides which rank
// does what.
#include <sys/types.h>

#include <filesystem>
#include <string_view>

namespace catena::io {

// "<target>.tmp-<pid>", in the target's directory (rename must not cross file systems).
std::filesystem::path temporary_sibling(const std::filesystem::path& target, pid_t pid);

// Writes `contents` to `path` (created or truncated) and fsyncs it before closing.
// Throws catena::Error naming the path and the failing system call.
void write_file_durably(const std::filesystem::path& path, std::string_view contents);

// Replaces `path` by a file holding `contents`: written to a temporary sibling, synced, renamed
// over it. Throws catena::OutputError naming the path and the failing call; the temporary is
// removed.
void write_file_atomically(const std::filesystem::path& path, std::string_view contents);

// Flushes a file's or a directory's data and metadata to storage (open + fsync + close).
void fsync_path(const std::filesystem::path& path);

// rename(2) `from` to `to`, replacing `to`. Throws catena::Error on failure.
void rename_into_place(const std::filesystem::path& from, const std::filesystem::path& to);

// Owns a temporary file name: unless released, the destructor removes the file if it is a
// regular file (never a directory or anything else that happens to carry the name).
class TemporaryFile {
 public:
  explicit TemporaryFile(std::filesystem::path path) : path_(std::move(path)) {}
  ~TemporaryFile();
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;

  const std::filesystem::path& path() const { return path_; }
  // Call once the file has been renamed into place: there is nothing left to remove.
  void release() { released_ = true; }

 private:
  std::filesystem::path path_;
  bool released_ = false;
};

// Not collective (the rank that owns the temporaries). Renames a written HDF5 result and
// then its XDMF description into place and syncs their directory, releasing both
// temporaries. HDF5 first: it is the result. Two renames cannot be one atomic step; if the
// second fails (both names were checked up front, so only a system fault can do it), the
// HDF5 file is complete and the error says the XDMF is missing.
void publish_with_xdmf(TemporaryFile& hdf5, const std::filesystem::path& hdf5_path,
                       TemporaryFile& xdmf, const std::filesystem::path& xdmf_path);

}  // namespace catena::io
