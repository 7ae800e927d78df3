#include "catena/post/butterworth.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

#include "catena/core/error.hpp"

namespace catena::post {
namespace {

// One pass of the section over `x` into `y` (transposed direct form II), starting from the
// steady state for the constant input x[0] (output x[0]: the DC gain is 1).
void run_section(const BiquadCoefficients& c, std::span<const double> x, std::span<double> y) {
  if (x.empty()) return;
  // Steady state for x = y = x0: z2 = (b2 − a2) x0, z1 = (1 − b0) x0
  // (b0 + b1 + b2 = 1 + a1 + a2, the unit DC gain).
  double z1 = (1.0 - c.b0) * x[0];
  double z2 = (c.b2 - c.a2) * x[0];
  for (std::size_t n = 0; n < x.size(); ++n) {
    const double out = c.b0 * x[n] + z1;
    z1 = c.b1 * x[n] - c.a1 * out + z2;
    z2 = c.b2 * x[n] - c.a2 * out;
    y[n] = out;
  }
}

void check_arguments(double dt, double cutoff_hz) {
  if (!(dt > 0.0) || !std::isfinite(dt)) {
    std::ostringstream os;
    os << "sampling interval " << dt << " s: must be positive and finite";
    throw InputError({"", 0, "dt"}, os.str());
  }
  const double nyquist = 0.5 / dt;
  if (!(cutoff_hz > 0.0) || !(cutoff_hz < nyquist)) {
    std::ostringstream os;
    os << "low-pass cutoff " << cutoff_hz << " Hz: must be positive and below the Nyquist "
       << "frequency " << nyquist << " Hz of the sampling interval " << dt << " s";
    throw InputError({"", 0, "cutoff"}, os.str());
  }
}

}  // namespace

BiquadCoefficients butterworth_lowpass_biquad(double dt, double cutoff_hz) {
  check_arguments(dt, cutoff_hz);
  const double k = std::tan(std::numbers::pi * cutoff_hz * dt);  // prewarped Ωc T / 2
  const double k2 = k * k;
  const double a0 = 1.0 + std::numbers::sqrt2 * k + k2;
  BiquadCoefficients c;
  c.b0 = k2 / a0;
  c.b1 = 2.0 * c.b0;
  c.b2 = c.b0;
  c.a1 = 2.0 * (k2 - 1.0) / a0;
  c.a2 = (1.0 - std::numbers::sqrt2 * k + k2) / a0;
  return c;
}

double butterworth_zero_phase_gain(double dt, double cutoff_hz, double frequency_hz) {
  check_arguments(dt, cutoff_hz);
  const double ratio =
      std::tan(std::numbers::pi * frequency_hz * dt) / std::tan(std::numbers::pi * cutoff_hz * dt);
  const double r2 = ratio * ratio;
  return 1.0 / (1.0 + r2 * r2);
}

std::vector<double> butterworth_lowpass_zero_phase(std::span<const double> signal, double dt,
                                                   double cutoff_hz) {
  const BiquadCoefficients c = butterworth_lowpass_biquad(dt, cutoff_hz);
  std::vector<double> forward(signal.size());
  run_section(c, signal, forward);
  // Backward: run over the reversed forward output, then reverse back.
  std::vector<double> reversed(forward.rbegin(), forward.rend());
  std::vector<double> backward(signal.size());
  run_section(c, reversed, backward);
  return {backward.rbegin(), backward.rend()};
}

}  // namespace catena::post
