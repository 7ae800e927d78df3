#pragma once
// Richardson's estimate of a run's time-discretisation error from the same run at 2 dt and
// 4 dt (`catena run --error-bar`; docs/accuracy.md, "Error bar of a run"), with the order
// of convergence observed from the three runs instead of assumed — contact, dropper
// slackening and element crossings make a pantograph run's order differ from the method's.
//
// For a quantity S with S(h) = S* + C hᵖ: S(2h) − S(h) = (2ᵖ − 1) C hᵖ and
// S(4h) − S(2h) = 2ᵖ (2ᵖ − 1) C hᵖ, so 2ᵖ = [S(4h) − S(2h)] / [S(2h) − S(h)] and the run's
// error S(h) − S* = [S(2h) − S(h)] / (2ᵖ − 1): the same sign as the coarser runs' deviation. For a
// norm of a difference of series (an RMS), ‖X(2h) − X(h)‖ = (2ᵖ − 1) E and ‖X(4h) − X(h)‖ = (4ᵖ −
// 1) E, so 2ᵖ = ratio − 1. Where the three runs are not in that regime (the differences change
// sign, or the observed order is below 1/2 or above 6), the estimate is the bound p = 1 gives,
// S(2h) − S(h) itself, and the order is reported as NaN.
//
// Not collective: plain numbers.
#include <cstddef>
#include <optional>
#include <vector>

#include "catena/io/error_bar_record.hpp"
#include "catena/study/study_table.hpp"

namespace catena::study {

// One quantity. `signed_difference`: S(2h) − S(h) and S(4h) − S(h) (any unit); otherwise
// the norms ‖X(2h) − X(h)‖ and ‖X(4h) − X(h)‖. Fills estimate and order.
void richardson(double at_2dt, double at_4dt, bool signed_difference, io::ErrorBarEntry& out);

// Every quantity `study::CaseErrors` measured (not NaN) for the runs at 2 dt and 4 dt
// against the run itself: the EN 50318 statistics (% of the run's value), the filtered
// contact force's RMS difference (N), the probe track's (m).
std::vector<io::ErrorBarEntry> richardson_error_bar(const CaseErrors& at_2dt,
                                                    const CaseErrors& at_4dt);

// The cases of a study a row's error bar comes from: completed rows of the same method
// whose only varied resolution key is integrator.dt, at 2 and 4 times the row's.
struct DtSiblings {
  std::size_t at_2dt = 0, at_4dt = 0;
};
// Not collective. Per row, its siblings if the study has both.
std::vector<std::optional<DtSiblings>> dt_siblings(const std::vector<StudyRow>& rows);

}  // namespace catena::study
