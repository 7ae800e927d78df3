#pragma once
// Richardson's estimate of a run's time-discretisation error from the same run at 2 dt and
// 4 dt (`catena run --error-bar`; docs/accuracy.md, "Error bar of a run"), with the order
// of convergence observed from the three runs instead of assumed — contact, dropper
// slackening and element crossings make a pantograph run's order differ from the method's.
//
// For a quantity S with S(h) = S* + C hᵖ: S(2h) − S(h) = (2ᵖ − 1) C hᵖ and
// S(4h) − S(2h) = 2ᵖ (2ᵖ − 1) C hᵖ, so 2ᵖ = [S(4h) − S(2h)] / [S(2h) − S(h)], and the
// run's error S(h) − S* = [S(2h) − S(h)] / (2ᵖ − 1), of the sign of the coarser runs'
// deviation. For a norm of a difference of series (an RMS), ‖X(2h) − X(h)‖ = (2ᵖ − 1) E
// and ‖X(4h) − X(h)‖ = (4ᵖ − 1) E, so 2ᵖ = ratio − 1 and E = ‖X(2h) − X(h)‖ / (2ᵖ − 1).
//
// Where the three runs do not converge at one order the estimate is a rough size, and the
// order is reported as NaN: an observed order outside [1/2, 6] is clamped to that range
// (below 1/2 the error is larger still, above 6 smaller), and differences of opposite sign
// (an oscillating convergence) give S(2h) − S(h) itself — the run then lies between its
// coarser neighbour and the limit if the oscillation decays, which three runs cannot show.
//
// Not collective: plain numbers.
#include <cstddef>
#include <optional>
#include <vector>

#include "catena/io/error_bar_record.hpp"
#include "catena/study/case_measures.hpp"
#include "catena/study/study_table.hpp"

namespace catena::study {

// One quantity. `signed_difference`: S(2h) − S(h) and S(4h) − S(h) (any unit); otherwise
// the norms ‖X(2h) − X(h)‖ and ‖X(4h) − X(h)‖. Fills estimate and order.
void richardson(double at_2dt, double at_4dt, bool signed_difference, io::ErrorBarEntry& out);

// Per part (pantograph or probe) of the run, every quantity measured (not NaN) for the
// runs at 2 dt and 4 dt against the run itself (ReferenceRun::errors_by_part of both, in
// the same order): the EN 50318 statistics (% of the run's value), the filtered contact
// force's RMS difference (N), the probe track's (m).
std::vector<io::ErrorBarEntry> richardson_error_bar(const std::vector<PartErrors>& at_2dt,
                                                    const std::vector<PartErrors>& at_4dt);

// The largest estimate (in magnitude) of each measure over the parts, one entry per
// measure (part ""): the study's columns, which hold each measure's worst over the parts.
std::vector<io::ErrorBarEntry> worst_estimates(const std::vector<io::ErrorBarEntry>& entries);

// The cases of a study a row's error bar comes from: completed rows of the same method
// whose only varied resolution key is integrator.dt, at 2 and 4 times the row's.
struct DtSiblings {
  std::size_t at_2dt = 0, at_4dt = 0;
};
// Not collective. Per row, its siblings if the study has both.
std::vector<std::optional<DtSiblings>> dt_siblings(const std::vector<StudyRow>& rows);

}  // namespace catena::study
