// The memory estimate (catena/model/memory_estimate.hpp) and the reader's checks against
// a budget: counts of a known model, linear growth, the integrator's multiple, and a scene
// of 10⁷ elements refused before its lines are generated (so at once), naming the key,
// the estimate and the limit.
#include <gtest/gtest.h>

#include <string>

#include "catena/core/error.hpp"
#include "catena/model/memory_estimate.hpp"
#include "catena/model/scene_reader.hpp"

namespace {

using namespace catena;
using namespace catena::model;

constexpr double kGiB = 1024.0 * 1024.0 * 1024.0;

// A pinned wire of `elements` cable elements, as text; `extra` is appended.
std::string wire_scene(long elements, const std::string& extra = "") {
  return "sections:\n"
         "  cw: {type: cable, EA: 1.8e7, EI: 195, mass_per_length: 1.35}\n"
         "nodes:\n"
         "  - {id: 1, position: [0, 0, 0]}\n"
         "  - {id: 2, position: [100, 0, 0]}\n"
         "lines:\n"
         "  - {name: wire, from: 1, to: 2, elements: " +
         std::to_string(elements) +
         ", section: cw, tension: 20000}\n"
         "supports:\n"
         "  - {node: 1, fix: pinned}\n"
         "  - {node: 2, fix: pinned}\n" +
         extra;
}

MemoryBudget budget_of(double gib, int ranks = 1, int ranks_on_host = 1) {
  MemoryBudget b;
  b.host_bytes = gib * kGiB;
  b.ranks = ranks;
  b.ranks_on_host = ranks_on_host;
  return b;
}

InputError input_error_of(const std::string& text, const MemoryBudget& budget) {
  try {
    parse_scene(text, "big.yaml", {}, budget);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError";
  return InputError({}, "");
}

TEST(ProblemSize, CountsNodesDofsAndBlocksOfACableChain) {
  const ProblemSize size = problem_size(parse_scene(wire_scene(10), "wire.yaml"));
  EXPECT_EQ(size.nodes, 11);
  EXPECT_EQ(size.elements, 10);
  EXPECT_EQ(size.dofs, 66);  // 6 per node (position and slope)
  // 11 diagonal 6x6 blocks and two off-diagonal ones per element.
  EXPECT_EQ(size.matrix_nonzeros, 11 * 36 + 10 * 2 * 36);
  EXPECT_EQ(size.factor_multiple, 2.0);  // statics: the tangent and its stability LDLᵀ
}

TEST(ProblemSize, ImplicitRungeKuttaNeedsStagesTimesTheLinearAlgebra) {
  const std::string dynamic = "analysis: {type: dynamic, duration: 1}\n";
  EXPECT_EQ(problem_size(parse_scene(wire_scene(10, dynamic), "w.yaml")).factor_multiple, 2.0);
  EXPECT_EQ(
      problem_size(
          parse_scene(wire_scene(10, dynamic + "integrator: {type: radau, stages: 3}\n"), "w.yaml"))
          .factor_multiple,
      6.0);
  EXPECT_EQ(problem_size(parse_scene(wire_scene(10, dynamic + "integrator: {type: radau, stages: "
                                                              "3, linear_algebra: coupled}\n"),
                                     "w.yaml"))
                .factor_multiple,
            9.0);
}

TEST(MemoryEstimate, GrowsLinearlyAndRanksOnAHostShareAllButTheModel) {
  const MemoryEstimate small = estimate_memory(problem_size(parse_scene(wire_scene(1000), "a")));
  const MemoryEstimate large = estimate_memory(problem_size(parse_scene(wire_scene(2000), "b")));
  EXPECT_NEAR(large.per_host_bytes(1, 1) / small.per_host_bytes(1, 1), 2.0, 0.01);
  // Two ranks on one host: the model twice, the rest once.
  EXPECT_NEAR(small.per_host_bytes(2, 2) - small.per_host_bytes(1, 1), small.model_bytes, 1.0);
  // Two hosts of one rank: each holds the model and half the rest.
  EXPECT_LT(small.per_host_bytes(2, 1), small.per_host_bytes(1, 1));
  // Ten million cable elements are tens of GiB, a thousand well under one.
  const MemoryEstimate huge = estimate_memory(
      ProblemSize{10'000'001, 10'000'000, 60'000'006, 10'000'001 * 36 + 10'000'000 * 72, 2.0});
  EXPECT_GT(huge.per_host_bytes(1, 1), 24 * kGiB);
  EXPECT_LT(small.per_host_bytes(1, 1), 0.05 * kGiB);
}

TEST(MemoryBudget, TenMillionElementsAreRefusedBeforeTheLineIsBuilt) {
  const InputError e = input_error_of(wire_scene(10'000'000), budget_of(24.0));
  const std::string message = e.what();
  EXPECT_EQ(e.where().key, "lines[0].elements") << message;
  EXPECT_EQ(e.where().line, 7) << message;
  // Refused by the count of the lines (before generating them), with the numbers.
  EXPECT_NE(message.find("the lines make 10000000 elements"), std::string::npos) << message;
  EXPECT_NE(message.find("needs an estimated"), std::string::npos) << message;
  EXPECT_NE(message.find("60000000 DOFs"), std::string::npos) << message;
  EXPECT_NE(message.find("more than the 24 GiB of physical memory of this host"), std::string::npos)
      << message;
  EXPECT_NE(message.find("--memory-limit"), std::string::npos) << message;
}

TEST(MemoryBudget, TheBuiltModelIsCheckedToo) {
  // Explicit elements are not counted in advance: the complete model's check names them.
  const std::string text =
      "sections:\n"
      "  cw: {type: cable, EA: 1.8e7, EI: 195, mass_per_length: 1.35}\n"
      "nodes:\n"
      "  - {id: 1, position: [0, 0, 0]}\n"
      "  - {id: 2, position: [10, 0, 0]}\n"
      "elements:\n"
      "  - {id: 1, nodes: [1, 2], section: cw}\n"
      "supports:\n"
      "  - {node: 1, fix: pinned}\n"
      "  - {node: 2, fix: pinned}\n";
  EXPECT_NO_THROW(parse_scene(text, "small.yaml", {}, budget_of(1.0)));
  const InputError e = input_error_of(text, budget_of(1e-7));  // 107 bytes
  EXPECT_EQ(e.where().key, "elements[0]") << e.what();
  EXPECT_NE(std::string(e.what()).find("the scene makes 1 elements"), std::string::npos)
      << e.what();
}

TEST(MemoryBudget, RanksOnOneHostEachHoldTheModel) {
  const std::string text = wire_scene(100'000);
  const MemoryEstimate one =
      estimate_memory(problem_size(parse_scene(text, "w.yaml", {}, budget_of(24.0))));
  // A limit between the 1-rank and the 64-ranks-per-host need.
  const double limit = 0.5 * (one.per_host_bytes(1, 1) + one.per_host_bytes(64, 64)) / kGiB;
  EXPECT_NO_THROW(parse_scene(text, "w.yaml", {}, budget_of(limit, 1, 1)));
  const InputError e = input_error_of(text, budget_of(limit, 64, 64));
  EXPECT_NE(std::string(e.what()).find("64 ranks on it"), std::string::npos) << e.what();
  EXPECT_NE(std::string(e.what()).find("fewer ranks per host"), std::string::npos) << e.what();
}

// A run that shares its host with other runs of the job (a study's groups, the comparison
// runs of --error-bar-ranks) is checked against its share, and the refusal says so.
TEST(MemoryBudget, ARunSharingItsHostIsCheckedAgainstItsShare) {
  MemoryBudget shared = budget_of(8.0, 1, 1);
  shared.job_ranks_on_host = 3;
  EXPECT_EQ(shared.describe(),
            "8 GiB, this run's share of this host's physical memory (1 rank on it of the job's 3)");
  shared.from_option = true;
  EXPECT_EQ(shared.describe(),
            "8 GiB, this run's share of the --memory-limit per host (1 rank on it of the job's 3)");
  const InputError e = input_error_of(wire_scene(10'000'000), shared);
  EXPECT_NE(std::string(e.what()).find("this run's share"), std::string::npos) << e.what();
}

TEST(MemoryBudget, AnInactiveBudgetChecksNothing) {
  EXPECT_NO_THROW(parse_scene(wire_scene(1000), "w.yaml", {}, MemoryBudget{}));
}

}  // namespace
