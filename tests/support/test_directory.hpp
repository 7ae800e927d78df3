#pragma once
// A fresh directory per test for tests that write files, shared by every rank of
// MPI_COMM_WORLD (mpi tests run on 1, 2 and 3 ranks, and several at once under ctest -j).
#include <filesystem>
#include <string>
#include <vector>

namespace catena::test {

// Collective (MPI_COMM_WORLD). Rank 0's process id, on every rank: the writers name their
// temporary files after it.
long long root_process_id();

// Collective (MPI_COMM_WORLD). An empty directory for the running test, the same path on
// every rank: <temp>/<prefix>_<test name>_np<ranks>_<rank 0's pid> (made afresh).
std::filesystem::path fresh_test_directory(const std::string& prefix);

// Collective (MPI_COMM_WORLD). Removes `directory` (rank 0) once every rank is done with it.
void remove_test_directory(const std::filesystem::path& directory);

// Not collective. The names in `directory`, sorted.
std::vector<std::string> directory_listing(const std::filesystem::path& directory);

}  // namespace catena::test
