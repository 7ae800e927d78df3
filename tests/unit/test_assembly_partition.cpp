// METIS element partition: every element gets a part, a connected line gets contiguous
// parts, and a disconnected element graph (a pantograph beside its wire: the moving
// contact is no element) is partitioned without METIS printing an error.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <set>
#include <string>
#include <vector>

#include "catena/assembly/partition.hpp"
#include "model_builders.hpp"

namespace {

using namespace catena;

model::CableProps wire() {
  model::CableProps c;
  c.EA = 1.8e7;
  c.EI = 195.0;
  c.mass_per_length = 1.35;
  return c;
}

// Elements of part `p` form one run of consecutive elements along a line.
bool part_is_one_run(const std::vector<int>& owner, int p) {
  const auto first = std::find(owner.begin(), owner.end(), p);
  const auto last = std::find(owner.rbegin(), owner.rend(), p).base();
  return first != owner.end() && std::all_of(first, last, [&](int o) { return o == p; });
}

TEST(Partition, ConnectedLineSplitsIntoContiguousParts) {
  model::Model m;
  test::add_line(m, Vec3(0, 0, 0), Vec3(100, 0, 0), 60, wire());
  for (const int n_parts : {2, 3}) {
    const std::vector<int> owner = assembly::partition_elements(m, n_parts);
    ASSERT_EQ(owner.size(), 60u);
    EXPECT_EQ(std::set<int>(owner.begin(), owner.end()).size(), static_cast<size_t>(n_parts));
    for (int p = 0; p < n_parts; ++p) EXPECT_TRUE(part_is_one_run(owner, p)) << "part " << p;
  }
}

TEST(Partition, DisconnectedGraphIsPartitionedSilently) {
  model::Model m;
  test::add_line(m, Vec3(0, 0, 0), Vec3(100, 0, 0), 60, wire());
  test::add_line(m, Vec3(0, 0, -2), Vec3(0, 0, -1), 1, model::SpringProps{});
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  const std::vector<int> owner = assembly::partition_elements(m, 2);
  std::fflush(stdout);
  const std::string printed = testing::internal::GetCapturedStdout();
  const std::string errors = testing::internal::GetCapturedStderr();
  // METIS writes "METIS Error: A contiguous partition is requested for a non-contiguous
  // input graph." when asked for CONTIG here.
  EXPECT_EQ(printed + errors, "");
  ASSERT_EQ(owner.size(), 61u);
  for (const int o : owner) EXPECT_TRUE(o == 0 || o == 1);
  EXPECT_EQ(std::set<int>(owner.begin(), owner.end()).size(), 2u);
}

}  // namespace
