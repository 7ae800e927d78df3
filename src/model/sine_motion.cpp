#include "sine_motion.hpp"

namespace catena::model::detail {

double read_sine_frequency(const Field& frequency, bool amplitude_is_zero,
                           const std::string& amplitude_unit) {
  if (amplitude_is_zero) {
    if (frequency.present())
      frequency.fail("frequency is given but amplitude is zero or missing; give amplitude [" +
                     amplitude_unit + "] too, or drop frequency");
    return 0.0;
  }
  if (!frequency.present())
    frequency.fail(
        "missing required key (amplitude is nonzero); expected the frequency of the sine "
        "motion, a finite number > 0 [Hz]");
  return frequency.real(RealRange::positive("Hz"));
}

}  // namespace catena::model::detail
