// A write that fails on one rank only becomes the same catena::OutputError on every rank,
// at np 1, 2 and 3: the failure is injected on the last rank (the testing hook of
// catena/io/write_fault_injection.hpp: the HDF5 call runs, then reports "No space left on
// device" on that rank) into each writer — the time series (a sample, a step flush, the
// close), the checkpoint and the static result. Every rank must throw the same message,
// naming the file, the object and the cause; a rank left behind in a collective call
// would hang the test (ctest's timeout). Afterwards the files are as the writers promise:
// the time series closed with status "failed: ...", the previous checkpoint and the
// previous static result untouched, no temporary file left.
#include <gtest/gtest.h>
#include <hdf5.h>
#include <mpi.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/core/mpi_comm.hpp"
#include "catena/io/checkpoint.hpp"
#include "catena/io/hdf5_writer.hpp"
#include "catena/io/output_error.hpp"
#include "catena/io/transient_writer.hpp"
#include "catena/io/write_fault_injection.hpp"
#include "model_builders.hpp"
#include "test_directory.hpp"

namespace {

namespace fs = std::filesystem;
using catena::io::WriteFault;
using catena::test::directory_listing;

int comm_rank() { return catena::mpi_rank(MPI_COMM_WORLD); }
int comm_size() { return catena::mpi_size(MPI_COMM_WORLD); }

// The rank that fails: the last one, so that at np > 1 it is not the rank that prints.
int failing_rank() { return comm_size() - 1; }

// A straight 8-element line; rows owned round-robin (scattered over the ranks).
catena::model::Model line_model() {
  catena::model::Model model;
  model.name = "line";
  model.source_file = "line.yaml";
  model.source_text = "a line";
  catena::test::add_line(model, {0, 0, 0}, {8, 0, 0}, 8, catena::model::CableProps{});
  return model;
}

std::vector<int> my_rows(int n_rows) {
  std::vector<int> rows;
  for (int row = comm_rank(); row < n_rows; row += comm_size()) rows.push_back(row);
  return rows;
}

std::vector<double> values_per_row(const std::vector<int>& rows, int per_row, double scale) {
  std::vector<double> values;
  for (const int row : rows)
    for (int k = 0; k < per_row; ++k) values.push_back(scale * row + k);
  return values;
}

// Collective. Runs `write`; returns the OutputError's message ("" if it did not throw).
// Any other exception fails the test.
std::string output_error_of(const std::function<void()>& write) {
  try {
    write();
  } catch (const catena::OutputError& error) {
    return error.what();
  } catch (const std::exception& other) {
    ADD_FAILURE() << "rank " << comm_rank() << " threw another error: " << other.what();
    return "another error";
  }
  return {};
}

// Collective. Expects the same non-empty message on every rank, containing each of
// `expected` and (if `names_the_rank`) naming the failing rank when there are several.
void expect_same_error_on_every_rank(const std::string& message,
                                     const std::vector<std::string>& expected,
                                     bool names_the_rank = true) {
  EXPECT_FALSE(message.empty()) << "rank " << comm_rank() << " did not throw";
  for (const std::string& text : expected)
    EXPECT_NE(message.find(text), std::string::npos) << "'" << text << "' not in: " << message;
  if (names_the_rank && comm_size() > 1) {
    EXPECT_NE(message.find("(on rank " + std::to_string(failing_rank()) + ")"), std::string::npos)
        << message;
  }
  std::string on_rank_0 = message;
  int length = static_cast<int>(on_rank_0.size());
  MPI_Bcast(&length, 1, MPI_INT, 0, MPI_COMM_WORLD);
  on_rank_0.resize(static_cast<std::size_t>(length));
  MPI_Bcast(on_rank_0.data(), length, MPI_CHAR, 0, MPI_COMM_WORLD);
  EXPECT_EQ(message, on_rank_0) << "rank " << comm_rank() << " throws another message";
}

// Not collective. A string attribute of the root group of `path` (serial HDF5).
std::string root_string_attribute(const fs::path& path, const char* name) {
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0) return "<unreadable file>";
  std::string value = "<no attribute>";
  const hid_t attribute = H5Aopen(file, name, H5P_DEFAULT);
  if (attribute >= 0) {
    const hid_t type = H5Aget_type(attribute);
    char* text = nullptr;
    if (H5Aread(attribute, type, &text) >= 0 && text != nullptr) value = text;
    H5free_memory(text);
    H5Tclose(type);
    H5Aclose(attribute);
  }
  H5Fclose(file);
  return value;
}

// A fresh directory per test, shared by all ranks; no fault armed before or after.
class WriteFailureTest : public ::testing::Test {
 protected:
  void SetUp() override {
    catena::io::set_write_fault(std::nullopt);
    directory_ = catena::test::fresh_test_directory("catena_test_write_failures");
  }

  void TearDown() override {
    catena::io::set_write_fault(std::nullopt);
    catena::test::remove_test_directory(directory_);
  }

  static void inject(std::int64_t call, const std::string& at) {
    catena::io::set_write_fault(WriteFault{failing_rank(), call, at});
  }

  // Collective. A time-series writer for line_model() at `path`.
  std::unique_ptr<catena::io::TransientWriter> transient_writer(const fs::path& path) const {
    catena::io::RunInfo info;
    info.n_ranks = comm_size();
    return std::make_unique<catena::io::TransientWriter>(MPI_COMM_WORLD, path.string(), model_,
                                                         info, my_rows(int(model_.nodes.size())),
                                                         my_rows(int(model_.elements.size())));
  }

  // Collective. One sample of made-up values.
  void append_sample(catena::io::TransientWriter& writer, double t) const {
    const std::vector<int> nodes = my_rows(int(model_.nodes.size()));
    const std::vector<int> elements = my_rows(int(model_.elements.size()));
    writer.append_sample(t, values_per_row(nodes, 3, 1.0), values_per_row(nodes, 3, 2.0),
                         values_per_row(nodes, 3, 0.0), values_per_row(elements, 1, 10.0));
  }

  const catena::model::Model model_ = line_model();
  fs::path directory_;
};

TEST_F(WriteFailureTest, SampleWriteFailingOnOneRankFailsOnEveryRankAndTheFileClosesAsFailed) {
  const fs::path path = directory_ / "run.h5";
  const auto writer = transient_writer(path);
  append_sample(*writer, 0.0);
  writer->flush();
  inject(1, "/samples/velocities");  // the next sample's velocities, written by a flush
  append_sample(*writer, 0.1);       // buffered
  const std::string message = output_error_of([&] { writer->flush(); });
  expect_same_error_on_every_rank(
      message, {"H5Dwrite failed for '" + path.string() + "' at /samples/velocities",
                "No space left on device"});
  // The file is not written again after a failure: every rank refuses alike.
  expect_same_error_on_every_rank(output_error_of([&] { append_sample(*writer, 0.2); }),
                                  {"not written again after a failed write"}, false);
  // The failure was injected after a complete write: the file can still be closed.
  EXPECT_EQ(output_error_of([&] { writer->close("failed: " + message, {}); }), "");
  if (comm_rank() == 0) {
    EXPECT_EQ(root_string_attribute(path, "status"), "failed: " + message);
  }
}

TEST_F(WriteFailureTest, StepFlushFailingOnOneRankFailsOnEveryRank) {
  const fs::path path = directory_ / "run.h5";
  const auto writer = transient_writer(path);
  append_sample(*writer, 0.0);
  for (int k = 1; k <= 3; ++k) writer->append_step({0.01 * k, 0.01, 2, -1.0, 0, {}, {}});
  inject(1, "/steps/dt");
  expect_same_error_on_every_rank(
      output_error_of([&] { writer->flush(); }),
      {"H5Dwrite failed for '" + path.string() + "' at /steps/dt", "No space left on device"});
  EXPECT_EQ(output_error_of([&] { writer->close("failed: flush", {}); }), "");
  if (comm_rank() == 0) {
    EXPECT_EQ(root_string_attribute(path, "status"), "failed: flush");
  }
}

// close() flushes (H5Fflush: write call 1), records the status and closes (H5Fclose:
// call 2), which fails: reported on every rank, once, and the file is not closed again.
TEST_F(WriteFailureTest, FailingCloseOnOneRankFailsOnEveryRank) {
  const fs::path path = directory_ / "run.h5";
  const auto writer = transient_writer(path);
  append_sample(*writer, 0.0);
  writer->flush();
  inject(2, "");  // after close's flush (no rows buffered: H5Fflush only)
  expect_same_error_on_every_rank(
      output_error_of([&] { writer->close("complete", {}); }),
      {"H5Fclose failed for '" + path.string() + "'", "No space left on device"});
  EXPECT_EQ(output_error_of([&] { writer->close("complete", {}); }), "") << "closed once only";
}

TEST_F(WriteFailureTest, FailingCheckpointOnOneRankKeepsThePreviousCheckpoint) {
  const fs::path path = directory_ / "run.h5.chk";
  const std::vector<int> nodes = my_rows(int(model_.nodes.size()));
  catena::io::CheckpointShare share;
  share.nodes = nodes;
  share.q = values_per_row(nodes, 12, 1.0);
  share.v = values_per_row(nodes, 12, 2.0);
  share.a = values_per_row(nodes, 12, 3.0);
  catena::io::CheckpointFacts facts{1.5, 0.01, 3, 30, "hht", "run", "test"};
  catena::io::write_checkpoint(MPI_COMM_WORLD, path.string(), model_, facts, share);

  inject(1, ".chk");  // the next checkpoint's first dataset
  facts.time = 2.5;
  expect_same_error_on_every_rank(
      output_error_of([&] {
        catena::io::write_checkpoint(MPI_COMM_WORLD, path.string(), model_, facts, share);
      }),
      {"cannot write the checkpoint '" + path.string() + "'", "H5Dwrite failed", "at /q",
       "No space left on device"});
  catena::io::set_write_fault(std::nullopt);
  const catena::io::Checkpoint kept =
      catena::io::read_checkpoint(MPI_COMM_WORLD, path.string(), model_, "hht");
  EXPECT_EQ(kept.facts.time, 1.5);
  MPI_Barrier(MPI_COMM_WORLD);
  if (comm_rank() == 0) {
    EXPECT_EQ(directory_listing(directory_), std::vector<std::string>{"run.h5.chk"});
  }
}

TEST_F(WriteFailureTest, FailingStaticWriteOnOneRankKeepsThePreviousResult) {
  const fs::path path = directory_ / "line.h5";
  if (comm_rank() == 0) std::ofstream(path) << "an older result";
  MPI_Barrier(MPI_COMM_WORLD);
  catena::io::StaticResult result;
  result.owned_nodes = my_rows(int(model_.nodes.size()));
  result.positions = values_per_row(result.owned_nodes, 3, 1.0);
  result.slopes = values_per_row(result.owned_nodes, 3, 0.0);
  result.owned_elements = my_rows(int(model_.elements.size()));
  result.axial_force = values_per_row(result.owned_elements, 1, 10.0);
  result.axial_strain = values_per_row(result.owned_elements, 1, 1e-4);
  result.shear_force = values_per_row(result.owned_elements, 3, 1.0);
  result.bending_moment = values_per_row(result.owned_elements, 3, 2.0);
  result.torsion = values_per_row(result.owned_elements, 1, 0.5);
  catena::io::RunInfo info;
  info.n_ranks = comm_size();
  inject(1, "/static/slopes");
  expect_same_error_on_every_rank(
      output_error_of([&] {
        catena::io::write_static_result(MPI_COMM_WORLD, path.string(), model_, result, info);
      }),
      {"cannot write '" + path.string() + "'", "H5Dwrite failed", "at /static/slopes",
       "No space left on device"});
  MPI_Barrier(MPI_COMM_WORLD);
  if (comm_rank() != 0) return;
  std::ifstream kept(path);
  std::stringstream text;
  text << kept.rdbuf();
  EXPECT_EQ(text.str(), "an older result");
  EXPECT_EQ(directory_listing(directory_), std::vector<std::string>{"line.h5"});
}

TEST(WriteFaultSpecification, ParsesRankCallAndPlace) {
  const WriteFault fault = catena::io::parse_write_fault("rank=1,call=7,at=/samples/positions");
  EXPECT_EQ(fault.rank, 1);
  EXPECT_EQ(fault.call, 7);
  EXPECT_EQ(fault.at, "/samples/positions");
  EXPECT_EQ(catena::io::parse_write_fault("call=2,rank=0").at, "");
}

TEST(WriteFaultSpecification, RejectsWhatItDoesNotAccept) {
  for (const char* text : {"rank=1", "call=3", "rank=-1,call=1", "rank=0,call=0", "rank=0,call=x",
                           "rank=0,call=1,when=now", "rank=0;call=1"}) {
    try {
      catena::io::parse_write_fault(text);
      ADD_FAILURE() << text << " accepted";
    } catch (const catena::Error& error) {
      const std::string message = error.what();
      EXPECT_NE(message.find("CATENA_FAULT_INJECT_WRITE='" + std::string(text) + "'"),
                std::string::npos)
          << message;
      EXPECT_NE(message.find("accepted: rank=R,call=N[,at=TEXT]"), std::string::npos) << message;
    }
  }
}

}  // namespace
