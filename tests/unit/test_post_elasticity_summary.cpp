// The elasticity summary (post/elasticity_summary.hpp): max, min, mean and EN 50119's
// uniformity coefficient of a curve, by hand.
#include <gtest/gtest.h>

#include <vector>

#include "catena/post/elasticity_summary.hpp"

namespace {

using catena::post::summarize_elasticity;

TEST(ElasticitySummary, ByHand) {
  const std::vector<double> e{0.2, 0.5, 0.6, 0.5, 0.2};
  const auto s = summarize_elasticity(e);
  EXPECT_DOUBLE_EQ(s.max, 0.6);
  EXPECT_DOUBLE_EQ(s.min, 0.2);
  EXPECT_DOUBLE_EQ(s.mean, 2.0 / 5.0);
  EXPECT_DOUBLE_EQ(s.uniformity, 0.4 / 0.8);
  EXPECT_EQ(s.at_max, 2u);
  EXPECT_EQ(s.at_min, 0u);  // the first of equal values
}

TEST(ElasticitySummary, UniformAndFixedEnds) {
  const std::vector<double> uniform{0.4, 0.4, 0.4};
  EXPECT_DOUBLE_EQ(summarize_elasticity(uniform).uniformity, 0.0);
  const std::vector<double> anchored{0.0, 0.3, 0.0};  // a span ending at an anchor
  EXPECT_DOUBLE_EQ(summarize_elasticity(anchored).uniformity, 1.0);
  const std::vector<double> rigid{0.0, 0.0};
  EXPECT_DOUBLE_EQ(summarize_elasticity(rigid).uniformity, 0.0);
}

}  // namespace
