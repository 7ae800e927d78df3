// study::richardson against quantities with a known error S(h) = S* + C hᵖ, and its bound
// where three runs do not converge monotonically.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "catena/study/richardson.hpp"

namespace catena::study {
namespace {

TEST(Richardson, RecoversOrderAndErrorOfAPowerLaw) {
  for (const double p : {1.0, 2.0, 3.0, 5.0}) {
    const double c = 0.7, h = 0.1, exact = 26.0;
    const auto s = [&](double step) { return exact + c * std::pow(step, p); };
    io::ErrorBarEntry e;
    richardson(s(2 * h) - s(h), s(4 * h) - s(h), true, e);
    EXPECT_NEAR(e.order, p, 1e-6) << p;
    EXPECT_NEAR(e.estimate, s(h) - exact, 1e-6 * std::abs(s(h) - exact)) << p;
  }
}

TEST(Richardson, NormsOfDifferencesGiveTheRunsOwnError) {
  // ‖X(kh) − X(h)‖ = (kᵖ − 1) E for a series whose error is E(h) = E·(step/h)ᵖ along one shape.
  const double p = 2.0, error = 3e-4;
  io::ErrorBarEntry e;
  richardson((std::pow(2.0, p) - 1) * error, (std::pow(4.0, p) - 1) * error, false, e);
  EXPECT_NEAR(e.order, p, 1e-12);
  EXPECT_NEAR(e.estimate, error, 1e-15);
}

TEST(Richardson, DifferencesOfOppositeSignGiveTheNearerDifference) {
  io::ErrorBarEntry e;
  richardson(-0.030 - 0.004, 0.058 - 0.004, true, e);  // oscillating convergence
  EXPECT_TRUE(std::isnan(e.order));
  EXPECT_DOUBLE_EQ(e.estimate, -0.034);  // S(2h) − S(h)
}

TEST(Richardson, OrdersOutsideTheRangeAreClamped) {
  io::ErrorBarEntry e;
  richardson(1.0, 2.2, true, e);  // 2ᵖ = 1.2: p = 0.26, clamped to 1/2
  EXPECT_TRUE(std::isnan(e.order));
  EXPECT_NEAR(e.estimate, 1.0 / (std::sqrt(2.0) - 1.0), 1e-12);
  richardson(1e-6, 1.0, true, e);  // 2ᵖ ≈ 10⁶: clamped to 6
  EXPECT_TRUE(std::isnan(e.order));
  EXPECT_NEAR(e.estimate, 1e-6 / 63.0, 1e-18);
  richardson(0.0, 1.0, true, e);  // the runs at h and 2h agree
  EXPECT_EQ(e.estimate, 0.0);
}

TEST(Richardson, OnlyMeasuredQuantitiesAreReported) {
  CaseErrors a, b;
  a.probe_rms = 3e-4;
  b.probe_rms = 15e-4;  // 2ᵖ = 4: p = 2
  const auto entries = richardson_error_bar({{"node 31", a}}, {{"node 31", b}});
  ASSERT_EQ(entries.size(), 1u);
  EXPECT_EQ(entries[0].part, "node 31");
  EXPECT_EQ(entries[0].measure, "probe_rms");
  EXPECT_EQ(entries[0].unit, "m");
  EXPECT_NEAR(entries[0].order, 2.0, 1e-12);
  EXPECT_NEAR(entries[0].estimate, 1e-4, 1e-16);
}

TEST(Richardson, EachPantographOnItsOwnThenTheWorstForTheStudy) {
  // Two pantographs whose σ converge at different orders: each gets its own estimate.
  CaseErrors a2, a4, b2, b4;
  a2.std = 0.3;  // p = 1: 2ᵖ = (0.9 − 0.3)/0.3
  a4.std = 0.9;
  b2.std = -0.03;  // p = 2
  b4.std = -0.15;
  const auto entries = richardson_error_bar({{"leading", a2}, {"trailing", b2}},
                                            {{"leading", a4}, {"trailing", b4}});
  ASSERT_EQ(entries.size(), 2u);
  EXPECT_EQ(entries[0].part, "leading");
  EXPECT_NEAR(entries[0].order, 1.0, 1e-12);
  EXPECT_NEAR(entries[0].estimate, 0.3, 1e-12);
  EXPECT_EQ(entries[1].part, "trailing");
  EXPECT_NEAR(entries[1].order, 2.0, 1e-12);
  EXPECT_NEAR(entries[1].estimate, -0.01, 1e-12);
  const auto worst = worst_estimates(entries);
  ASSERT_EQ(worst.size(), 1u);
  EXPECT_EQ(worst[0].part, "");
  EXPECT_NEAR(worst[0].estimate, 0.3, 1e-12);
  EXPECT_NEAR(worst[0].order, 1.0, 1e-12);
}

StudyRow dt_row(const std::string& method, const std::string& setting, bool completed = true) {
  StudyRow r;
  r.method = method;
  r.setting = setting;
  r.completed = completed;
  return r;
}

TEST(DtSiblings, SameMethodAtTwiceAndFourTimesTheStep) {
  const std::vector<StudyRow> rows = {
      dt_row("reference", "integrator.dt=0.000125"), dt_row("hht", "integrator.dt=0.001"),
      dt_row("hht", "integrator.dt=5e-04"),          dt_row("hht", "integrator.dt=0.00025"),
      dt_row("radau", "integrator.dt=0.002"),        dt_row("radau", "integrator.dt=0.001"),
      dt_row("radau", "integrator.dt=0.0005"),       dt_row("linear", "integrator.dt=0.001", false),
      dt_row("linear", "integrator.dt=5e-04"),       dt_row("linear", "integrator.dt=0.00025"),
      dt_row("hht", "catenary.element_length=0.25")};
  const auto s = dt_siblings(rows);
  ASSERT_EQ(s.size(), rows.size());
  ASSERT_TRUE(s[3].has_value());  // hht at 0.25 ms: 0.5 and 1 ms
  EXPECT_EQ(s[3]->at_2dt, 2u);
  EXPECT_EQ(s[3]->at_4dt, 1u);
  EXPECT_FALSE(s[2].has_value());  // no hht at 2 ms
  EXPECT_FALSE(s[0].has_value());  // the reference is its own method
  ASSERT_TRUE(s[6].has_value());
  EXPECT_EQ(s[6]->at_4dt, 4u);
  EXPECT_FALSE(s[9].has_value());   // its run at 4 dt failed
  EXPECT_FALSE(s[10].has_value());  // not varied in the step
}

TEST(DtSiblings, EstimatesGoToTheirColumns) {
  StudyRow r = dt_row("hht", "integrator.dt=0.00025");
  r.estimates.push_back({"", "std", "%", -0.0079, 2.7});
  const std::string csv = csv_text({r});
  EXPECT_NE(csv.find(",std_error_estimate_percent,std_estimate_order,"), std::string::npos);
  EXPECT_NE(csv.find(",-0.0079,2.7,"), std::string::npos) << csv;
}

}  // namespace
}  // namespace catena::study
