// The differences `catena study` measures between two runs (src/post/run_difference.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "catena/core/error.hpp"
#include "catena/post/run_difference.hpp"

namespace catena::post {
namespace {

TEST(Resample, LinearIsExactAndTheEndsAreChecked) {
  const std::vector<double> t = {0.0, 0.1, 0.2, 0.3};
  const std::vector<double> y = {1.0, 1.5, 2.0, 2.5};  // 1 + 5 t
  const std::vector<double> at = {0.0, 0.05, 0.125, 0.3};
  const std::vector<double> r = resample_linear(t, y, at);
  for (std::size_t k = 0; k < at.size(); ++k) EXPECT_NEAR(r[k], 1.0 + 5.0 * at[k], 1e-14);
  const std::vector<double> beyond = {0.31};
  EXPECT_THROW(resample_linear(t, y, beyond), InputError);
  EXPECT_THROW(resample_linear(t, std::vector<double>{1.0}, at), Error);
}

PantographRecord record(std::size_t n, double dt, double offset) {
  PantographRecord p;
  p.name = "leading";
  p.speed = 50.0;
  for (std::size_t k = 0; k < n; ++k) {
    const double t = static_cast<double>(k) * dt;
    p.force.push_back(100.0 + offset + 10.0 * std::sin(2.0 * std::numbers::pi * 2.0 * t));
    p.position.push_back(50.0 * t);
  }
  return p;
}

TEST(ForceDifference, AConstantOffsetIsItsOwnRmsAndMaxRawAndFiltered) {
  const double dt = 1e-3;
  const PantographRecord reference = record(2001, dt, 0.0);
  const PantographRecord run = record(2001, dt, 2.0);
  const ForceDifference d = force_difference(run, reference, {dt, 20.0, {20.0, 80.0}});
  EXPECT_EQ(d.n_samples, 1201u);
  EXPECT_NEAR(d.rms_raw, 2.0, 1e-12);
  EXPECT_NEAR(d.max_raw, 2.0, 1e-12);
  EXPECT_NEAR(d.rms_filtered, 2.0, 1e-9);  // the filter passes a constant unchanged
  EXPECT_NEAR(d.max_filtered, 2.0, 1e-9);
  EXPECT_THROW(force_difference(record(2000, dt, 0.0), reference, {dt, 20.0, {20.0, 80.0}}), Error);
  EXPECT_THROW(force_difference(run, reference, {dt, 20.0, {500.0, 600.0}}), InputError);
}

TEST(ForceDifference, HighFrequencyNoiseIsRemovedByTheFilter) {
  const double dt = 1e-3;
  const PantographRecord reference = record(2001, dt, 0.0);
  PantographRecord run = reference;
  for (std::size_t k = 0; k < run.force.size(); ++k) run.force[k] += (k % 2 ? 1.0 : -1.0);
  const ForceDifference d = force_difference(run, reference, {dt, 20.0, {20.0, 80.0}});
  EXPECT_NEAR(d.rms_raw, 1.0, 1e-12);
  EXPECT_LT(d.rms_filtered, 1e-3);  // 500 Hz, far above the 20 Hz cut-off
}

TEST(TrackDifference, RmsAndMaxOfTheDistance) {
  const std::vector<double> reference = {0, 0, 0, 1, 0, 0};
  const std::vector<double> run = {0, 3, 4, 1, 0, 0};  // 5 m off, then on
  const TrackDifference d = track_difference(run, reference);
  EXPECT_DOUBLE_EQ(d.max, 5.0);
  EXPECT_DOUBLE_EQ(d.rms, std::sqrt(25.0 / 2.0));
  EXPECT_THROW(track_difference(run, std::vector<double>{0, 0}), Error);
}

TEST(RelativeError, FloorForReferencesNearZero) {
  EXPECT_DOUBLE_EQ(relative_error(101.0, 100.0, 1.0), 0.01);
  EXPECT_DOUBLE_EQ(relative_error(0.5, 0.0, 1.0), 0.5);
  EXPECT_DOUBLE_EQ(relative_error(-99.0, -100.0, 1.0), 0.01);
}

}  // namespace
}  // namespace catena::post
