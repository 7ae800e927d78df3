#include "test_directory.hpp"

#include <gtest/gtest.h>
#include <mpi.h>
#include <unistd.h>

#include <algorithm>

#include "catena/core/mpi_comm.hpp"

namespace catena::test {
namespace fs = std::filesystem;

long long root_process_id() {
  long long pid = ::getpid();
  MPI_Bcast(&pid, 1, MPI_LONG_LONG, 0, MPI_COMM_WORLD);
  return pid;
}

fs::path fresh_test_directory(const std::string& prefix) {
  const long long root_pid = root_process_id();
  const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path directory =
      fs::temp_directory_path() /
      (prefix + "_" + std::string(test->name()) + "_np" + std::to_string(mpi_size(MPI_COMM_WORLD)) +
       "_" + std::to_string(root_pid));
  if (mpi_rank(MPI_COMM_WORLD) == 0) {
    fs::remove_all(directory);
    fs::create_directories(directory);
  }
  MPI_Barrier(MPI_COMM_WORLD);
  return directory;
}

void remove_test_directory(const fs::path& directory) {
  MPI_Barrier(MPI_COMM_WORLD);
  if (mpi_rank(MPI_COMM_WORLD) == 0) fs::remove_all(directory);
}

std::vector<std::string> directory_listing(const fs::path& directory) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(directory))
    names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace catena::test
