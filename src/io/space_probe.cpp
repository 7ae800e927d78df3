#include "space_probe.hpp"

#include <unistd.h>

#include <string>

#include "catena/core/error.hpp"
#include "catena/core/mpi_comm.hpp"
#include "catena/io/atomic_file.hpp"

namespace catena::io {

std::string failed_test_write_beside(MPI_Comm comm, const std::filesystem::path& path) {
  std::string why;
  if (mpi_rank(comm) == 0) {
    std::filesystem::path probe = path;
    probe += ".probe";
    const TemporaryFile removed_at_exit(temporary_sibling(probe, ::getpid()));
    try {
      write_file_durably(removed_at_exit.path(), std::string(std::size_t{1} << 20, '\0'));
    } catch (const Error& error) {
      why = error.what();
    }
  }
  broadcast_string(comm, why);
  return why;
}

}  // namespace catena::io
