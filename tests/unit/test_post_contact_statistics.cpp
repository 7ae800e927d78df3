// The zero-phase Butterworth low-pass and the EN 50318 contact-force statistics
// (include/catena/post/).
//  - Filter: the section's coefficients (unit DC gain, |H(fc)| = 1/√2 from the transfer
//    function); the measured amplitude ratio of filtered sines — 1 at DC (a constant passes
//    exactly), 1/2 (−6.02 dB) at the cutoff, G(5 fc) = 1/(1 + (tan(5πfcT)/tan(πfcT))⁴) —
//    against the closed form G(f) on a sweep; zero phase (a filtered sine has no lag).
//    Gains are measured by projecting the middle of a 4 s record on sin and cos over whole
//    periods (the end transients have decayed there by e^−40): tolerance 1e-9 absolute.
//  - Statistics against hand-computed values: F0 + A sin(2π f t) over a section of 10 whole
//    periods plus one zero sample has mean F0 and σ = A G(f) √(2500/5001); the sampled
//    peaks hit sin = ±1 exactly. Contact loss counts raw samples ≤ 0 in the section only;
//    uplift uses registration points inside the section, while the pantograph passes them.
//    Tolerance 1e-9 relative (sums of 5001 O(100) terms).
//  - Input errors: coarse sampling (naming the interval and the largest admissible one),
//    an empty or reversed section, a cutoff above Nyquist.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/post/butterworth.hpp"
#include "catena/post/contact_statistics.hpp"

namespace {

using catena::InputError;
using catena::post::butterworth_lowpass_biquad;
using catena::post::butterworth_lowpass_zero_phase;
using catena::post::butterworth_zero_phase_gain;
using catena::post::contact_statistics;
using catena::post::ContactStatisticsOptions;
using catena::post::PantographRecord;
using catena::post::RegistrationPoint;

constexpr double pi = std::numbers::pi;
constexpr double dt = 1e-3;      // s: 1 kHz sampling
constexpr double cutoff = 20.0;  // Hz

// The closed form the tests hold the filter to, written out independently of the library.
double expected_gain(double f) {
  const double r = std::tan(pi * f * dt) / std::tan(pi * cutoff * dt);
  return 1.0 / (1.0 + r * r * r * r);
}

struct Response {
  double gain = 0.0;   // amplitude out / in
  double phase = 0.0;  // rad, output relative to the input sine (negative: lag)
};

// Filters sin(2π f t) over 4 s and projects the output on sin and cos over the whole
// periods contained in [1 s, 3 s].
Response measure(double f) {
  const std::size_t n = 4000;
  std::vector<double> x(n);
  for (std::size_t k = 0; k < n; ++k) x[k] = std::sin(2.0 * pi * f * dt * static_cast<double>(k));
  const std::vector<double> y = butterworth_lowpass_zero_phase(x, dt, cutoff);
  const std::size_t first = 1000;
  // Whole periods in 2000 samples (f dt × 2000 is an integer for the frequencies used; the
  // guard keeps floor from losing one to rounding).
  const double periods = std::floor(2000.0 * f * dt + 1e-9);
  const auto count = static_cast<std::size_t>(std::lround(periods / (f * dt)));
  double s = 0.0, c = 0.0;
  for (std::size_t k = first; k < first + count; ++k) {
    const double w = 2.0 * pi * f * dt * static_cast<double>(k);
    s += y[k] * std::sin(w);
    c += y[k] * std::cos(w);
  }
  s *= 2.0 / static_cast<double>(count);
  c *= 2.0 / static_cast<double>(count);
  return {std::hypot(s, c), std::atan2(c, s)};
}

TEST(Butterworth, SectionHasUnitDcGainAndMinus3dBAtTheCutoff) {
  const auto c = butterworth_lowpass_biquad(dt, cutoff);
  // 1 + a1 + a2 = 4K²/a0 ≈ 0.015 here: the ratio loses two digits to cancellation.
  EXPECT_NEAR((c.b0 + c.b1 + c.b2) / (1.0 + c.a1 + c.a2), 1.0, 1e-13);
  const std::complex<double> z = std::polar(1.0, 2.0 * pi * cutoff * dt);
  const std::complex<double> zi = 1.0 / z;
  const std::complex<double> h =
      (c.b0 + c.b1 * zi + c.b2 * zi * zi) / (1.0 + c.a1 * zi + c.a2 * zi * zi);
  EXPECT_NEAR(std::abs(h), 1.0 / std::sqrt(2.0), 1e-14);
  EXPECT_DOUBLE_EQ(butterworth_zero_phase_gain(dt, cutoff, cutoff), 0.5);
}

TEST(Butterworth, ConstantPassesUnchanged) {
  const std::vector<double> x(3000, 114.5);
  const std::vector<double> y = butterworth_lowpass_zero_phase(x, dt, cutoff);
  ASSERT_EQ(y.size(), x.size());
  for (double v : y) EXPECT_NEAR(v, 114.5, 1e-11);
  EXPECT_TRUE(butterworth_lowpass_zero_phase(std::vector<double>{}, dt, cutoff).empty());
}

TEST(Butterworth, MeasuredGainsAtCutoffAndFiveTimesCutoff) {
  const Response at_cutoff = measure(cutoff);
  const Response at_5 = measure(5.0 * cutoff);
  std::printf(
      "measured zero-phase gain: f = fc %.15f (%.4f dB, phase %.1e rad), "
      "f = 5 fc %.9e (closed form %.9e, %.2f dB)\n",
      at_cutoff.gain, 20.0 * std::log10(at_cutoff.gain), at_cutoff.phase, at_5.gain,
      expected_gain(5.0 * cutoff), 20.0 * std::log10(at_5.gain));
  EXPECT_NEAR(at_cutoff.gain, 0.5, 1e-9);
  EXPECT_NEAR(at_5.gain, expected_gain(5.0 * cutoff), 1e-9);
  EXPECT_NEAR(at_5.gain, 1.4034e-3, 1e-6);  // 1/(1 + (tan(0.1π)/tan(0.02π))⁴) at 1 kHz
}

TEST(Butterworth, GainFollowsTheClosedFormWithZeroPhase) {
  for (double f : {1.0, 2.0, 5.0, 10.0, 15.0, 20.0, 25.0, 40.0, 100.0, 200.0}) {
    const Response r = measure(f);
    EXPECT_NEAR(r.gain, expected_gain(f), 1e-9) << "f = " << f << " Hz";
    EXPECT_NEAR(butterworth_zero_phase_gain(dt, cutoff, f), expected_gain(f), 1e-15);
    if (r.gain > 1e-3) {
      EXPECT_NEAR(r.phase, 0.0, 1e-8) << "f = " << f << " Hz";
    }
  }
}

TEST(Butterworth, FilteredSineHasNoLag) {
  // 8 Hz, inside the pass band: the output is G sin(ωt) sample by sample, its peaks where
  // the input's are.
  const double f = 8.0;
  std::vector<double> x(4000);
  for (std::size_t k = 0; k < x.size(); ++k)
    x[k] = std::sin(2.0 * pi * f * dt * static_cast<double>(k));
  const std::vector<double> y = butterworth_lowpass_zero_phase(x, dt, cutoff);
  double worst = 0.0;
  for (std::size_t k = 1000; k < 3000; ++k)
    worst = std::max(worst, std::abs(y[k] - expected_gain(f) * x[k]));
  EXPECT_LT(worst, 1e-9);
  // The peak of the period starting at 1 s (input peak at sample 1000 + 125/4 ≈ 1031).
  auto peak = [](const std::vector<double>& v) {
    std::size_t best = 1000;
    for (std::size_t k = 1000; k < 1125; ++k)
      if (v[k] > v[best]) best = k;
    return best;
  };
  EXPECT_EQ(peak(y), peak(x));
}

// Why the statistics of a record that ends inside the section leave out its last 2/cutoff
// seconds (apps/catena/run_statistics.cpp): the backward pass starts at the record's end from
// its last value, and on a contact-force-like signal (a mean, span-passing and dropper
// content, and content above the cutoff) the record cut short differs from the whole
// record's filtered force by 0.07 N one cutoff period before the cut and by 0.0015 N two
// periods before it.
TEST(Butterworth, EndTransientOfARecordCutShortDecaysWithinTwoCutoffPeriods) {
  const double fc = 20.0, two_pi = 2.0 * std::numbers::pi;  // dt: the file's 1 ms
  std::vector<double> x;
  for (int k = 0; k < 4000; ++k) {
    const double t = k * dt;
    x.push_back(120.0 + 30.0 * std::sin(two_pi * 2.0 * t) +
                15.0 * std::sin(two_pi * 9.0 * t + 1.0) + 8.0 * std::sin(two_pi * 37.0 * t + 0.3) +
                5.0 * std::sin(two_pi * 113.0 * t));
  }
  const std::vector<double> whole = butterworth_lowpass_zero_phase(x, dt, fc);
  const std::size_t cut = 3000;
  const std::vector<double> part =
      butterworth_lowpass_zero_phase(std::vector<double>(x.begin(), x.begin() + cut), dt, fc);
  auto largest_error_before = [&](double seconds) {
    const auto end = cut - static_cast<std::size_t>(std::lround(seconds / dt));
    double worst = 0.0;
    for (std::size_t k = 0; k < end; ++k) worst = std::max(worst, std::abs(part[k] - whole[k]));
    return worst;
  };
  EXPECT_GT(largest_error_before(0.25 / fc), 0.1);  // near the cut the transient is there
  EXPECT_LT(largest_error_before(2.0 / fc), 0.01);  // two periods back it is gone
}

TEST(Butterworth, RejectsCutoffAboveNyquist) {
  const std::vector<double> x(10, 1.0);
  EXPECT_THROW(butterworth_lowpass_zero_phase(x, dt, 600.0), InputError);
  EXPECT_THROW(butterworth_lowpass_zero_phase(x, dt, 0.0), InputError);
  EXPECT_THROW(butterworth_lowpass_zero_phase(x, 0.0, cutoff), InputError);
}

// F0 + A sin(2π f t), 10 s at 1 kHz; the contact point at x = 0.5 k m at sample k, so
// positions are exact and a section in metres is an exact range of samples.
PantographRecord sine_record(double f0, double amplitude, double f) {
  PantographRecord p;
  p.name = "leading";
  p.speed = 500.0;  // m/s: 0.5 m per 1 ms sample
  for (std::size_t k = 0; k < 10000; ++k) {
    p.force.push_back(f0 + amplitude * std::sin(2.0 * pi * f * dt * static_cast<double>(k)));
    p.position.push_back(0.5 * static_cast<double>(k));
  }
  return p;
}

ContactStatisticsOptions section_options(double x_start, double x_end) {
  ContactStatisticsOptions o;
  o.dt = dt;
  o.cutoff_hz = cutoff;
  o.section = {x_start, x_end};
  return o;
}

TEST(ContactStatistics, ConstantPlusSineAgainstClosedForm) {
  const double f0 = 115.0, amplitude = 30.0, f = 2.0;  // 500 samples per period
  const PantographRecord p = sine_record(f0, amplitude, f);
  // [1250, 3750] m = samples 2500 … 7500: 10 whole periods plus sample 7500 (sin = 0).
  const auto s = contact_statistics(p, {}, section_options(1250.0, 3750.0));
  const double g = expected_gain(f);
  const double sigma = amplitude * g * std::sqrt(2500.0 / 5001.0);
  EXPECT_EQ(s.n_samples, 5001u);
  EXPECT_NEAR(s.mean, f0, 1e-9 * f0);
  EXPECT_NEAR(s.standard_deviation, sigma, 1e-9 * sigma);
  EXPECT_NEAR(s.statistical_max, f0 + 3.0 * sigma, 1e-9 * f0);
  EXPECT_NEAR(s.statistical_min, f0 - 3.0 * sigma, 1e-9 * f0);
  EXPECT_NEAR(s.max, f0 + amplitude * g, 1e-9 * f0);
  EXPECT_NEAR(s.min, f0 - amplitude * g, 1e-9 * f0);
  EXPECT_EQ(s.contact_loss_percent, 0.0);
  EXPECT_EQ(s.n_supports, 0u);
  EXPECT_FALSE(s.max_uplift_at_support.has_value());
}

TEST(ContactStatistics, FiltersTheWholeRecordNotJustTheSection) {
  // A section starting mid-record sees the steady filtered sine at its first sample: had
  // only the section been filtered, its edges would start from the raw value.
  const PantographRecord p = sine_record(115.0, 30.0, 2.0);
  const auto whole = contact_statistics(p, {}, section_options(1250.0, 3750.0));
  PantographRecord cut;
  cut.name = p.name;
  for (std::size_t k = 2500; k <= 7500; ++k) {
    cut.force.push_back(p.force[k]);
    cut.position.push_back(p.position[k]);
  }
  const auto cut_only = contact_statistics(cut, {}, section_options(1250.0, 3750.0));
  EXPECT_NEAR(whole.standard_deviation, cut_only.standard_deviation, 1e-3);  // same physics
  const std::vector<double> filtered = butterworth_lowpass_zero_phase(p.force, dt, cutoff);
  EXPECT_NEAR(filtered[2500], 115.0, 1e-9);  // sin = 0 there: steady state, no transient
}

// The contact position of the sample at a section end is stored as 240.0 or as
// 239.99999999998892 m depending on the step sequence that reached it: both are in.
TEST(ContactStatistics, SampleCountDoesNotDependOnRoundOffAtTheSectionEnds) {
  PantographRecord p = sine_record(115.0, 30.0, 2.0);  // x = 0.5 k m, 500 m/s, 1 ms
  const auto exact = contact_statistics(p, {}, section_options(1250.0, 3750.0));
  p.position[2500] = std::nextafter(1250.0, 0.0) - 1e-11;  // below the start by round-off
  p.position[7500] = 3750.0 * (1.0 + 4e-14);               // beyond the end by round-off
  const auto rounded = contact_statistics(p, {}, section_options(1250.0, 3750.0));
  EXPECT_EQ(exact.n_samples, 5001u);
  EXPECT_EQ(rounded.n_samples, exact.n_samples);
  EXPECT_EQ(rounded.standard_deviation, exact.standard_deviation);
  // A sample a hundredth of the spacing (5 mm) outside stays out.
  p.position[7500] = 3750.005;
  EXPECT_EQ(contact_statistics(p, {}, section_options(1250.0, 3750.0)).n_samples, 5000u);
}

TEST(ContactStatistics, ContactLossCountsRawZerosInsideTheSectionOnly) {
  PantographRecord p;
  p.name = "trailing";
  for (std::size_t k = 0; k < 3000; ++k) {
    p.force.push_back(100.0);
    p.position.push_back(0.1 * static_cast<double>(k));
  }
  // Section [100, 199.9] m = samples 1000 … 1999 (x = 0.1 k, 1000 samples).
  for (std::size_t k = 1200; k < 1237; ++k) p.force[k] = 0.0;  // 37 lost samples inside
  p.force[1500] = -1e-12;                                      // ≤ 0 counts too
  for (std::size_t k = 100; k < 400; ++k) p.force[k] = 0.0;    // outside: not counted
  const auto s = contact_statistics(p, {}, section_options(99.95, 199.95));
  EXPECT_EQ(s.n_samples, 1000u);
  EXPECT_NEAR(s.contact_loss_percent, 3.8, 1e-12);
}

TEST(ContactStatistics, UpliftAtSupportsInsideTheSectionWhileThePantographPassesThem) {
  // Contact position 0.5 k m at sample k; section samples 2500 … 7500.
  const PantographRecord p = sine_record(115.0, 0.0, 1.0);
  // Supports at 1250 (the section's start), 2000, 3750 (its end) and 4000 m: each one's
  // window is the pantograph between its neighbours.
  RegistrationPoint inside{2000.0, std::vector<double>(10000, 5.3)};
  inside.z[4000] = 5.35;  // +0.05 m with the head at 2000 m
  inside.z[9000] = 5.5;   // +0.2 m with the head at 4500 m, past the next support: not counted
  RegistrationPoint start{1250.0, std::vector<double>(10000, 5.3)};
  start.z[2500] = 5.36;  // the section is closed: its end points belong to it
  RegistrationPoint end{3750.0, std::vector<double>(10000, 5.3)};
  end.z[7600] = 5.37;  // +0.07 m with the head 50 m past it (outside the section): counted
  RegistrationPoint outside{4000.0, std::vector<double>(10000, 5.3)};
  outside.z[5000] = 6.3;  // reference x outside the section: ignored
  const std::vector<RegistrationPoint> supports{inside, start, end, outside};
  const auto s = contact_statistics(p, supports, section_options(1250.0, 3750.0));
  EXPECT_EQ(s.n_supports, 3u);
  ASSERT_TRUE(s.max_uplift_at_support.has_value());
  EXPECT_NEAR(*s.max_uplift_at_support, 0.07, 1e-12);
  // Without the end support the largest is the start's, inside its window.
  const std::vector<RegistrationPoint> no_end{inside, start, outside};
  const auto s2 = contact_statistics(p, no_end, section_options(1250.0, 3750.0));
  ASSERT_TRUE(s2.max_uplift_at_support.has_value());
  EXPECT_NEAR(*s2.max_uplift_at_support, 0.06, 1e-12);

  const std::vector<RegistrationPoint> far{outside};
  const auto none = contact_statistics(p, far, section_options(1250.0, 3750.0));
  EXPECT_EQ(none.n_supports, 0u);
  EXPECT_FALSE(none.max_uplift_at_support.has_value());
}

std::string message_of(const PantographRecord& p, const ContactStatisticsOptions& o) {
  try {
    (void)contact_statistics(p, {}, o);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(ContactStatistics, RejectsCoarseSamplingNamingTheInterval) {
  PantographRecord p = sine_record(115.0, 0.0, 1.0);
  ContactStatisticsOptions o = section_options(1250.0, 3750.0);
  o.dt = 0.01;  // 100 Hz < 10 × 20 Hz
  const std::string m = message_of(p, o);
  EXPECT_NE(m.find("0.01 s"), std::string::npos) << m;
  EXPECT_NE(m.find("200 Hz"), std::string::npos) << m;
  EXPECT_NE(m.find("at most 0.005 s"), std::string::npos) << m;
  o.dt = 0.005;  // exactly 10 × the cutoff: accepted
  EXPECT_EQ(message_of(p, o), "no error");
}

TEST(ContactStatistics, RejectsEmptyOrReversedSections) {
  const PantographRecord p = sine_record(115.0, 0.0, 1.0);  // x from 0 to 4999.5 m
  const std::string m = message_of(p, section_options(6000.0, 7000.0));
  EXPECT_NE(m.find("no sample in the evaluation section"), std::string::npos) << m;
  EXPECT_NE(m.find("[0, 4999.5] m"), std::string::npos) << m;
  EXPECT_NE(message_of(p, section_options(3000.0, 2000.0)).find("x_start < x_end"),
            std::string::npos);
}

}  // namespace
