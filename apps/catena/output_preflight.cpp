#include "output_preflight.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <system_error>

#include "catena/core/error.hpp"
#include "catena/core/mpi_comm.hpp"

namespace catena::app {
namespace {

namespace fs = std::filesystem;

// Why a file cannot be made in `directory` (known to exist as a directory), or "".
std::string creation_problem(const fs::path& directory) {
  const fs::path probe = directory / (".catena-probe-" + std::to_string(::getpid()));
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd < 0) {
    const int error = errno;
    if (error == EEXIST) return "";  // a probe of ours left behind: the directory is writable
    return std::string("cannot create files in directory ") + directory.string() + ": " +
           std::strerror(error);
  }
  ::close(fd);
  ::unlink(probe.c_str());
  return "";
}

// Why an existing `file` cannot be replaced or written, or "".
std::string existing_file_problem(const fs::path& file) {
  std::error_code ec;
  if (fs::is_directory(file, ec)) return file.string() + " is a directory";
  if (::access(file.c_str(), W_OK) != 0)
    return file.string() + " exists and cannot be written: " + std::strerror(errno);
  return "";
}

}  // namespace

std::string output_path_problem(const std::string& path) {
  const fs::path file(path);
  const fs::path directory = file.has_parent_path() ? file.parent_path() : fs::path(".");
  std::error_code ec;
  const fs::file_status status = fs::status(directory, ec);
  if (!fs::exists(status)) {
    // The nearest ancestor that exists says whether a file stands in the way.
    fs::path ancestor = directory;
    while (ancestor.has_parent_path() && ancestor.parent_path() != ancestor &&
           !fs::exists(ancestor, ec))
      ancestor = ancestor.parent_path();
    if (fs::exists(ancestor, ec) && !fs::is_directory(ancestor, ec))
      return ancestor.string() + " is a file, not a directory";
    return "directory " + directory.string() + " does not exist";
  }
  if (!fs::is_directory(status)) return directory.string() + " is a file, not a directory";
  if (fs::exists(file, ec))
    if (std::string why = existing_file_problem(file); !why.empty()) return why;
  fs::path checkpoint = file;
  checkpoint += ".chk";
  if (fs::exists(checkpoint, ec))
    if (std::string why = existing_file_problem(checkpoint); !why.empty()) return why;
  return creation_problem(directory);
}

void check_output_path(MPI_Comm comm, const model::Model& m, bool from_command_line) {
  const std::string key = from_command_line ? "-o" : "output.file";
  // The same on every rank: a name, not the file system.
  if (const std::string extension = fs::path(m.output.file).extension().string();
      extension == ".xmf" || extension == ".xmf2")
    throw InputError({m.source_file, 0, key},
                     "the output file '" + m.output.file + "' ends in " + extension +
                         ", the name of an XDMF description Catena writes beside the HDF5 "
                         "results; expected an HDF5 name such as '" +
                         fs::path(m.output.file).replace_extension(".h5").string() + "'");
  std::string problem;
  if (mpi_rank(comm) == 0) problem = output_path_problem(m.output.file);
  broadcast_string(comm, problem);
  if (problem.empty()) return;
  throw InputError({m.source_file, 0, key},
                   "cannot write the output file '" + m.output.file + "': " + problem +
                       "; expected a path in an existing, writable directory (the checkpoint "
                       "'" +
                       m.output.file + ".chk' goes beside it)");
}

void check_modal_basis_path(MPI_Comm comm, const model::Model& m) {
  const std::string& path = m.dynamic_options.modal_basis;
  if (m.analysis != model::AnalysisType::dynamic || path.empty()) return;
  std::string problem;
  if (mpi_rank(comm) == 0) {
    std::error_code error;
    if (fs::exists(path, error))
      problem = fs::is_regular_file(path, error) ? "" : "it exists but is not a regular file";
    else
      problem = output_path_problem(path);
  }
  broadcast_string(comm, problem);
  if (problem.empty()) return;
  throw InputError({m.source_file, 0, "analysis.modal_basis"},
                   "cannot use the modal basis '" + path + "': " + problem +
                       "; expected an existing basis file or a path in an existing, writable "
                       "directory where the run writes one");
}

}  // namespace catena::app
