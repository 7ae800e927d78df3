#pragma once
// How far one dynamic run is from another (`catena study`: a setting against the reference;
// docs/study.md, "Error measures"). Pure functions of sampled series: no files, no MPI.
//
// Both series are sampled on the reference's times; a run sampled on other times is first
// brought to them by linear interpolation (resample_linear), which is exact for runs of the
// same output.interval (dense output at the same instants) and otherwise adds an
// interpolation error of O(interval²) that the study reports as the run's own.
#include <span>
#include <vector>

#include "catena/post/contact_statistics.hpp"

namespace catena::post {

// Not collective. `values` (one per time of `times`, ascending) at each of `at`, linear
// between neighbours; a time of `at` outside [times.front(), times.back()] by more than
// 1e-9 of the span throws catena::InputError (key "time"), so that a run that stopped
// early is not extended by its last value. Both may be empty (empty result).
std::vector<double> resample_linear(std::span<const double> times, std::span<const double> values,
                                    std::span<const double> at);

// The difference of two contact-force records over the evaluation section.
struct ForceDifference {
  std::size_t n_samples = 0;  // samples of the reference in the section
  double rms_raw = 0.0;       // N, RMS of (run − reference), raw penalty force
  double max_raw = 0.0;       // N, largest |run − reference|, raw
  double rms_filtered = 0.0;  // N, the same of both forces low-pass filtered at the cutoff
  double max_filtered = 0.0;  // N
};

// Not collective. `run` and `reference` sampled on the same times every `options.dt`
// (resample first); the section samples are the reference's whose contact position lies in
// options.section (as contact_statistics takes them); filtering as contact_statistics
// (whole record, zero-phase Butterworth at options.cutoff_hz). Throws catena::InputError as
// contact_statistics for bad sampling or an empty section, catena::Error when the lengths
// disagree.
ForceDifference force_difference(const PantographRecord& run, const PantographRecord& reference,
                                 const ContactStatisticsOptions& options);

// The difference of two trajectories of one point: RMS and largest Euclidean distance.
struct TrackDifference {
  double rms = 0.0;  // m
  double max = 0.0;  // m
};

// Not collective. `run` and `reference` are n × 3 positions (row-major) at the same n times.
// Throws catena::Error when the lengths disagree or are not a multiple of 3.
TrackDifference track_difference(std::span<const double> run, std::span<const double> reference);

// Not collective. (value − reference) / |reference|; when |reference| is below `floor`
// (a statistic that is zero in the reference, e.g. a minimum of 0 N), relative to `floor`.
double relative_error(double value, double reference, double floor);

}  // namespace catena::post
