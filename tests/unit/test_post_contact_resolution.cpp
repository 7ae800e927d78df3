// post::ContactResolution against its closed form: a sine of angular frequency ω stepped
// every h has roughness 4 sin²(ωh/2) (the second difference of sin(ωkh) is
// −4 sin²(ωh/2) sin(ωkh)).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "catena/post/contact_resolution.hpp"

namespace catena::post {
namespace {

double sine_roughness(double steps_per_period, double mean) {
  ContactResolution r;
  const double omega_h = 2.0 * std::numbers::pi / steps_per_period;
  // Whole periods (to a step), so that the sample spread is the sine's own.
  const int n = static_cast<int>(std::round(400.0 * steps_per_period));
  for (int k = 0; k < n; ++k) r.add(mean + 30.0 * std::sin(omega_h * k + 0.3));
  return r.roughness();
}

TEST(ContactResolution, SineFollowsItsClosedForm) {
  for (const double steps : {4.0, 8.7, 20.0, 100.0}) {
    const double expected = 4.0 * std::pow(std::sin(std::numbers::pi / steps), 2);
    EXPECT_NEAR(sine_roughness(steps, 120.0), expected, 2e-3 * expected) << steps;
  }
}

TEST(ContactResolution, LimitLiesAtAboutNineStepsPerPeriod) {
  EXPECT_FALSE(sine_roughness(9.5, 120.0) > ContactResolution::kUnresolved);
  EXPECT_TRUE(sine_roughness(8.0, 120.0) > ContactResolution::kUnresolved);
}

TEST(ContactResolution, TwoStepChatterIsFour) {
  ContactResolution r;
  for (int k = 0; k < 1000; ++k) r.add(k % 2 == 0 ? 0.0 : 200.0);  // contact lost every other step
  EXPECT_NEAR(r.roughness(), 4.0, 1e-2);
  EXPECT_TRUE(r.unresolved());
}

TEST(ContactResolution, ConstantOrShortSeriesIsZero) {
  ContactResolution r;
  r.add(120.0);
  r.add(130.0);
  EXPECT_EQ(r.roughness(), 0.0);  // fewer than three steps
  ContactResolution c;
  for (int k = 0; k < 100; ++k) c.add(120.0);
  EXPECT_EQ(c.roughness(), 0.0);  // no spread
  EXPECT_EQ(c.steps(), 100u);
}

}  // namespace
}  // namespace catena::post
