#pragma once
// Zero-phase Butterworth low-pass filter for uniformly sampled signals (post-processing:
// the 0–20 Hz band of EN 50317 / EN 50318 contact-force statistics).
//
// Design. The 2nd-order analogue Butterworth prototype
//     H(s) = Ωc² / (s² + √2 Ωc s + Ωc²)
// is mapped to z by the bilinear transform s = (2/T)(1 − z⁻¹)/(1 + z⁻¹) with the cutoff
// prewarped, Ωc = (2/T) tan(π fc T), so that the digital filter, not only its analogue
// prototype, has |H(fc)| = 1/√2 exactly. With K = tan(π fc T) the section is
//     H(z) = K² (1 + 2 z⁻¹ + z⁻²) / ((1 + √2 K + K²) + 2 (K² − 1) z⁻¹ + (1 − √2 K + K²) z⁻²)
// and its magnitude is |H(f)|² = 1 / (1 + (tan(π f T) / K)⁴) for 0 ≤ f < 1/(2T).
//
// Zero phase. The section is run forward over the whole record, then backward over the
// result (Gustafsson's "filtfilt"): the phase shifts cancel and the magnitude response is
// |H(f)|², i.e.
//     G(f) = 1 / (1 + (tan(π f T) / tan(π fc T))⁴):
// G(0) = 1, G(fc) = 1/2 (−6.02 dB), −3 dB at ≈ 0.80 fc, a 4th-order (−80 dB/decade) roll-off.
// Why: the statistics (maximum, minimum, the peak over a support) must not be shifted in
// time — and so along the line — or distorted by the phase lag of a causal filter; the
// Butterworth response is maximally flat in the pass band, so the mean and the slow
// span-passing content are left untouched, and the 2nd-order section applied twice is the
// usual choice for this band (its −6 dB point, not −3 dB, is the nominal 20 Hz).
//
// Ends of the record. Each pass starts from the section's steady state for the first value
// it sees (as if the signal had been constant before the record), so a constant signal
// passes unchanged and a record starting at rest has no start-up transient; any other
// start-up decays within a few 1/fc. Callers filter the whole record and evaluate inside it.
#include <span>
#include <vector>

namespace catena::post {

// One 2nd-order section, direct form:
//   y[n] = b0 x[n] + b1 x[n−1] + b2 x[n−2] − a1 y[n−1] − a2 y[n−2]   (a0 = 1).
struct BiquadCoefficients {
  double b0 = 0.0;
  double b1 = 0.0;
  double b2 = 0.0;
  double a1 = 0.0;
  double a2 = 0.0;
};

// Not collective. The prewarped bilinear-transform 2nd-order Butterworth low-pass for the
// sampling interval dt [s] and the cutoff cutoff_hz [Hz] (its −3 dB point).
// Throws catena::InputError (key "cutoff") unless dt > 0 and 0 < cutoff_hz < 1/(2 dt).
BiquadCoefficients butterworth_lowpass_biquad(double dt, double cutoff_hz);

// Not collective. G(f) = |H(f)|² of the zero-phase (forward–backward) filter at
// frequency_hz ∈ [0, 1/(2 dt)) [Hz]: the amplitude ratio out/in of a sine; 1/2 at the cutoff.
double butterworth_zero_phase_gain(double dt, double cutoff_hz, double frequency_hz);

// Not collective. `signal` sampled every dt [s], low-pass filtered at cutoff_hz [Hz] with
// the 2nd-order section above applied forward and backward (zero phase, |H|², −6 dB at
// cutoff_hz). Same length as `signal`; an empty signal gives an empty result.
// Throws catena::InputError as butterworth_lowpass_biquad.
std::vector<double> butterworth_lowpass_zero_phase(std::span<const double> signal, double dt,
                                                   double cutoff_hz);

}  // namespace catena::post
