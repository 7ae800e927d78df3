// The EN 50318 acceptance checks: the published ranges at 250 and 300 km/h (EN 50318:2002 as
// reproduced by Wang et al., IEEE Trans. Power Delivery 2016, Table III), closed intervals
// compared unrounded, the uplift in mm, other speeds without ranges.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "catena/post/en50318_ranges.hpp"

namespace catena::post {
namespace {

// A run inside every range at 250 km/h (the validation table's values, docs/validation.md).
ContactStatistics validated_250() {
  ContactStatistics s;
  s.mean = 117.0;
  s.standard_deviation = 28.8;
  s.statistical_max = 203.3;
  s.statistical_min = 30.8;
  s.max = 185.3;
  s.min = 60.0;
  s.contact_loss_percent = 0.0;
  s.max_uplift_at_support = 0.0505;  // m
  return s;
}

std::map<std::string, AcceptanceCheck> by_statistic(const std::vector<AcceptanceCheck>& checks) {
  std::map<std::string, AcceptanceCheck> out;
  for (const AcceptanceCheck& c : checks) out[c.statistic] = c;
  return out;
}

TEST(En50318Ranges, TheValidatedRunPassesAllEightAt250) {
  const auto checks = check_en50318(validated_250(), 250.0);
  ASSERT_TRUE(checks);
  ASSERT_EQ(checks->size(), 8u);
  for (const AcceptanceCheck& c : *checks) EXPECT_TRUE(c.pass) << c.statistic;
  const auto c = by_statistic(*checks);
  EXPECT_DOUBLE_EQ(c.at("max_uplift_at_support").value.value(), 50.5);  // mm
  EXPECT_EQ(c.at("max_uplift_at_support").unit, "mm");
  EXPECT_EQ(c.at("std").low, 26.0);
  EXPECT_EQ(c.at("std").high, 31.0);
}

TEST(En50318Ranges, At300TheSameRunFailsWhereTheRangesDiffer) {
  const auto c = by_statistic(*check_en50318(validated_250(), 300.0));
  EXPECT_TRUE(c.at("mean").pass);       // 110 – 120 at both speeds
  EXPECT_FALSE(c.at("std").pass);       // 32 – 40
  EXPECT_FALSE(c.at("stat_max").pass);  // 210 – 230
  EXPECT_FALSE(c.at("stat_min").pass);  // −5 – 20
  EXPECT_FALSE(c.at("max").pass);       // 190 – 225: 185.3 is below
  EXPECT_EQ(c.at("stat_min").low, -5.0);
}

TEST(En50318Ranges, EndsAreInsideAndTheValueIsNotRounded) {
  ContactStatistics s = validated_250();
  s.standard_deviation = 31.0;
  EXPECT_TRUE(by_statistic(*check_en50318(s, 250.0)).at("std").pass);
  s.standard_deviation = 31.004;  // prints as 31.00, still outside
  EXPECT_FALSE(by_statistic(*check_en50318(s, 250.0)).at("std").pass);
  s.contact_loss_percent = 0.05;  // any loss of contact fails
  EXPECT_FALSE(by_statistic(*check_en50318(s, 250.0)).at("contact_loss_percent").pass);
}

TEST(En50318Ranges, NoSupportInTheSectionIsNotMeasuredAndFails) {
  ContactStatistics s = validated_250();
  s.max_uplift_at_support.reset();
  const auto c = by_statistic(*check_en50318(s, 250.0));
  EXPECT_FALSE(c.at("max_uplift_at_support").value);
  EXPECT_FALSE(c.at("max_uplift_at_support").pass);
}

TEST(En50318Ranges, OnlyAt250And300KmH) {
  EXPECT_TRUE(check_en50318(validated_250(), 250.04));  // 69.4444 m/s printed rounded
  EXPECT_FALSE(check_en50318(validated_250(), 250.1));
  EXPECT_FALSE(check_en50318(validated_250(), 200.0));
  EXPECT_FALSE(check_en50318(validated_250(), 320.0));
}

}  // namespace
}  // namespace catena::post
