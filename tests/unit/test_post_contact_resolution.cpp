// post::ContactResolution against its closed form: a sine of angular frequency ω stepped
// every h has roughness 4 sin²(ωh/2) (the second difference of sin(ωkh) is
// −4 sin²(ωh/2) sin(ωkh)).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "catena/post/contact_resolution.hpp"
#include "catena/post/contact_strikes.hpp"

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

// A head that leaves the wire and lands again: losses and landings counted on the step
// series, a zero force being off the wire.
TEST(ContactStrikes, CountsLossesAndLandings) {
  ContactStrikes s;
  for (const double f : {120.0, 80.0, 0.0, 0.0, 150.0, 90.0, 0.0, 40.0, 0.0}) s.add(f);
  EXPECT_EQ(s.losses(), 3u);
  EXPECT_EQ(s.strikes(), 2u);
  EXPECT_FALSE(s.repeated());  // two strikes: below kRepeated
  s.add(60.0);
  EXPECT_EQ(s.strikes(), 3u);
  EXPECT_TRUE(s.repeated());
}

// Past the wire's wave speed the head leaves once and may come down once: not repeated. A
// head that starts off the wire (or before its path) lands without a loss: no strike; a
// contact never lost has none.
TEST(ContactStrikes, OneLandingIsNotRepeated) {
  ContactStrikes past;
  for (const double f : {120.0, 0.0, 0.0, 30.0, 0.0, 0.0}) past.add(f);
  EXPECT_EQ(past.strikes(), 1u);
  EXPECT_EQ(past.losses(), 2u);
  EXPECT_FALSE(past.repeated());
  ContactStrikes arriving;
  for (const double f : {0.0, 0.0, 30.0, 40.0}) arriving.add(f);
  EXPECT_EQ(arriving.strikes(), 0u);
  EXPECT_EQ(arriving.losses(), 0u);
  ContactStrikes steady;
  for (int k = 0; k < 100; ++k) steady.add(120.0 + 10.0 * std::sin(0.1 * k));
  EXPECT_EQ(steady.strikes(), 0u);
  EXPECT_EQ(steady.losses(), 0u);
}

}  // namespace
}  // namespace catena::post
