#pragma once
// EN 50318 contact-force statistics of one pantograph (docs/output.md, "Contact-force
// statistics"; docs/validation.md for the acceptance ranges): from a dynamic
// run's sampled contact force, contact position and registration-point heights, over an
// evaluation section [x_start, x_end] along the pantograph's path.
//
//   1. The raw contact force of the WHOLE record is low-pass filtered at the cutoff
//      (20 Hz by default) with the zero-phase Butterworth filter of butterworth.hpp
//      (2nd-order section forward and backward: |H|², −6 dB at the cutoff), so the
//      section's edges are not start-up transients of the filter.
//   2. The section samples are those whose contact position lies in [x_start, x_end],
//      the ends widened by round-off's reach (max(1e-6 of the distance between samples,
//      1e-9 of |x|)): a sample at an end is in, however its position was rounded.
//   3. Over them: mean F_m, population standard deviation σ, statistical maximum
//      F_m + 3σ and minimum F_m − 3σ, actual maximum and minimum — all of the FILTERED
//      force; the contact-loss percentage counts section samples whose RAW force is ≤ 0.
//   4. Uplift at support: z(t) − z(first sample) of every registration (steady-arm) point
//      whose reference x lies in the section, while the pantograph passes it — over the
//      samples whose contact position lies between the neighbouring registration points
//      (the line's ends where there is none) — the largest. Not the section samples only:
//      a support keeps rising just after the head has passed it, and the peak at the
//      section's last support would be cut. (With several pantographs, each pantograph's
//      uplift is attributed to it only if they run more than a span apart.)
//
// Pure functions of their arguments: no files, no MPI. SI units throughout.
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace catena::post {

// The sampling rate must be at least this many times the cutoff: the filtered force is
// then resolved with ≥ 10 samples per period of the highest frequency kept, so its sampled
// maximum and minimum are within ~5 % of the true peaks (1 − cos(π/10)).
inline constexpr double min_sampling_rate_per_cutoff = 10.0;

// One pantograph's samples (row k of each vector = sample k, every dt seconds).
struct PantographRecord {
  std::string name;
  double speed = 0.0;            // m/s, along the path
  std::vector<double> force;     // N, raw penalty contact force (≥ 0; 0 = loss of contact)
  std::vector<double> position;  // m, arc length of the contact point along the path
};

// A contact-wire registration (steady-arm) point.
struct RegistrationPoint {
  double reference_x = 0.0;  // m, x of its reference (mesh) position
  std::vector<double> z;     // m, its height at each sample; z[0] is the static position
};

struct EvaluationSection {
  double x_start = 0.0;  // m, along the path
  double x_end = 0.0;    // m, > x_start
};

struct ContactStatisticsOptions {
  double dt = 0.0;          // s, sampling interval
  double cutoff_hz = 20.0;  // Hz, low-pass cutoff (the filter's −6 dB point)
  EvaluationSection section;
};

struct ContactStatistics {
  std::size_t n_samples = 0;          // samples in the section
  double mean = 0.0;                  // N, filtered force
  double standard_deviation = 0.0;    // N, population σ of the filtered force
  double statistical_max = 0.0;       // N, mean + 3σ
  double statistical_min = 0.0;       // N, mean − 3σ
  double max = 0.0;                   // N, filtered force
  double min = 0.0;                   // N, filtered force
  double contact_loss_percent = 0.0;  // %, section samples with raw force ≤ 0
  std::size_t n_supports = 0;         // registration points whose reference x is in the section
  // m, largest z − z[0] of those points while the pantograph passes them (step 4 above);
  // none if n_supports == 0.
  std::optional<double> max_uplift_at_support;
};

// Not collective. The statistics of `pantograph` over `options.section`; `supports` are all
// the registration points of the line (those outside the section are ignored).
// Throws catena::InputError when
//   - the sampling rate 1/dt is below min_sampling_rate_per_cutoff × cutoff (key "dt",
//     naming the interval and the largest admissible one), or dt or the cutoff is not
//     positive and finite (key "cutoff");
//   - the section is empty or reversed (key "section");
//   - no sample of the pantograph lies in the section (key "section", naming the range of
//     contact positions the record covers);
// and catena::Error when the vectors' lengths disagree.
ContactStatistics contact_statistics(const PantographRecord& pantograph,
                                     std::span<const RegistrationPoint> supports,
                                     const ContactStatisticsOptions& options);

// Not collective. As above, with the whole record's force already filtered: `filtered` is
// butterworth_lowpass_zero_phase(pantograph.force, options.dt, options.cutoff_hz), for a
// caller that needs the filtered series too (it is not filtered again). Throws as above,
// and catena::Error when `filtered` is not as long as the record.
ContactStatistics contact_statistics(const PantographRecord& pantograph,
                                     std::span<const double> filtered,
                                     std::span<const RegistrationPoint> supports,
                                     const ContactStatisticsOptions& options);

// Not collective. The rows of `pantograph`'s samples in options.section (step 2 above),
// ascending. Throws catena::InputError (key "section") when the section is empty, reversed
// or holds no sample.
std::vector<std::size_t> section_samples(const PantographRecord& pantograph,
                                         const ContactStatisticsOptions& options);

}  // namespace catena::post
