// The modal basis file (io/modal_basis.hpp) on 1, 2 and 3 ranks: written with the rows
// spread over the ranks in one pattern (round robin: every rank's rows scattered) and read
// back in another (contiguous, reversed: rank 0 holds the last rows), every value must come
// back exactly; a read with a lower cut-off keeps the modes below it; a file of another
// model, a higher cut-off than stored, or a file that is no basis are refused on every rank
// with an InputError naming the file.
#include <gtest/gtest.h>
#include <mpi.h>

#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/io/modal_basis.hpp"

namespace {

namespace fs = std::filesystem;
using catena::io::BasisRows;

int rank_of() {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank;
}

int size_of() {
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  return size;
}

constexpr int kRows = 23;  // not a multiple of 2 or 3
const std::vector<double> kFrequency{1.5, 2.25, 7.0, 9.75};

// Value of row r of mode k: a function of the indices only.
double value(int mode, int row) { return 1000.0 * mode + row + 0.125; }

catena::model::Model model(int n_nodes) {
  catena::model::Model m;
  m.source_file = "scenes/basis.yaml";
  m.nodes.resize(static_cast<std::size_t>(n_nodes));
  m.elements.resize(4);
  return m;
}

BasisRows round_robin() {
  BasisRows rows{kRows, {}};
  for (int r = rank_of(); r < kRows; r += size_of()) rows.owned.push_back(r);
  return rows;
}

BasisRows reversed_blocks() {
  // Rank 0 the last block, the last rank the first: contiguous, but not in rank order.
  const int size = size_of(), part = size - 1 - rank_of();
  BasisRows rows{kRows, {}};
  for (int r = part * kRows / size; r < (part + 1) * kRows / size; ++r) rows.owned.push_back(r);
  return rows;
}

std::string path_of(const char* name) {
  std::string path = (fs::temp_directory_path() / name).string();
  MPI_Barrier(MPI_COMM_WORLD);
  return path;
}

void write(const std::string& path, const BasisRows& rows) {
  std::vector<std::vector<double>> values(kFrequency.size());
  std::vector<std::span<const double>> shapes;
  for (std::size_t k = 0; k < kFrequency.size(); ++k) {
    for (int r : rows.owned) values[k].push_back(value(static_cast<int>(k), r));
    shapes.emplace_back(values[k]);
  }
  catena::io::write_modal_basis(MPI_COMM_WORLD, path, model(10), rows, 10.0, kFrequency, shapes,
                                "test");
}

TEST(ModalBasis, ReadOnOtherRowsGivesEveryValueBack) {
  const std::string path = path_of("catena_test_modal_basis.h5");
  write(path, round_robin());
  const BasisRows rows = reversed_blocks();
  const catena::io::ModalBasis basis =
      catena::io::read_modal_basis(MPI_COMM_WORLD, path, model(10), rows, 10.0);
  EXPECT_EQ(basis.cutoff_hz, 10.0);
  ASSERT_EQ(basis.frequency, kFrequency);
  ASSERT_EQ(basis.shapes.size(), kFrequency.size());
  for (std::size_t k = 0; k < kFrequency.size(); ++k) {
    ASSERT_EQ(basis.shapes[k].size(), rows.owned.size());
    for (std::size_t i = 0; i < rows.owned.size(); ++i)
      EXPECT_EQ(basis.shapes[k][i], value(static_cast<int>(k), rows.owned[i]));
  }
  // A lower cut-off keeps the modes below it (the first three).
  const catena::io::ModalBasis below =
      catena::io::read_modal_basis(MPI_COMM_WORLD, path, model(10), rows, 8.0);
  EXPECT_EQ(below.frequency.size(), 3u);
  EXPECT_EQ(below.shapes.size(), 3u);
  MPI_Barrier(MPI_COMM_WORLD);
  if (rank_of() == 0) fs::remove(path);
}

// The InputError's message on this rank ("" if none was thrown).
std::string refusal(const std::string& path, int n_nodes, double cutoff) {
  try {
    catena::io::read_modal_basis(MPI_COMM_WORLD, path, model(n_nodes), round_robin(), cutoff);
  } catch (const catena::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ModalBasis, RefusesAnotherModelAHigherCutoffAndOtherFiles) {
  const std::string path = path_of("catena_test_modal_basis_refused.h5");
  write(path, round_robin());
  EXPECT_NE(refusal(path, 11, 10.0).find("n_nodes = 10 in the file, 11 in this scene"),
            std::string::npos)
      << refusal(path, 11, 10.0);
  EXPECT_NE(refusal(path, 10, 12.0).find("holds the modes below 10 Hz, this run asks for 12 Hz"),
            std::string::npos)
      << refusal(path, 10, 12.0);
  const std::string missing = path_of("catena_test_no_such_basis.h5");
  EXPECT_NE(refusal(missing, 10, 10.0).find("catena_test_no_such_basis.h5"), std::string::npos);
  MPI_Barrier(MPI_COMM_WORLD);
  if (rank_of() == 0) fs::remove(path);
}

}  // namespace
