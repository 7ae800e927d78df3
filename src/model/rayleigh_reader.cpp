#include "rayleigh_reader.hpp"

#include <cmath>
#include <numbers>

namespace catena::model::detail {

Rayleigh read_rayleigh(const Field& r) {
  if (!r.present()) return {};
  r.expect_map(
      "Rayleigh damping ({mass: alpha, stiffness: beta} or {ratio: zeta, "
      "frequencies: [f1, f2]})");
  r.check_keys({"mass", "stiffness", "ratio", "frequencies"});
  const Field mass = r.child("mass"), stiffness = r.child("stiffness");
  const Field ratio = r.child("ratio"), frequencies = r.child("frequencies");
  const bool by_coefficients = mass.present() || stiffness.present();
  const bool by_ratio = ratio.present() || frequencies.present();
  if (by_coefficients && by_ratio)
    r.fail(
        "give either the coefficients 'mass' (alpha, 1/s) and 'stiffness' (beta, s), or "
        "'ratio' with 'frequencies' (Hz), not both");
  if (!by_coefficients && !by_ratio)
    r.fail(
        "empty Rayleigh damping: give 'mass' (alpha, 1/s) and/or 'stiffness' (beta, s), "
        "or 'ratio' with 'frequencies' (Hz)");
  Rayleigh out;
  if (by_coefficients) {
    out.mass = mass.real_or(0.0, RealRange::non_negative("1/s"));
    out.stiffness = stiffness.real_or(0.0, RealRange::non_negative("s"));
    if (!out.active())
      r.fail(
          "both Rayleigh coefficients are zero: that is no damping; remove the key "
          "instead");
    return out;
  }
  const double zeta = ratio.real(RealRange::between(0.0, false, 1.0, false, ""));
  const std::vector<Field> f = frequencies.items();
  if (f.size() != 2)
    frequencies.fail("expected two frequencies [f1, f2] in Hz, got " + std::to_string(f.size()) +
                     " values");
  const double f1 = f[0].real(RealRange::positive("Hz"));
  const double f2 = f[1].real(RealRange::positive("Hz"));
  if (!(f2 > f1))
    frequencies.fail("expected f1 < f2 (the damping ratio is matched at both), got [" +
                     f[0].value_text() + ", " + f[1].value_text() + "]");
  // ζ(ω) = α/(2ω) + βω/2 equal to ζ at ω1 and ω2.
  const double w1 = 2.0 * std::numbers::pi * f1, w2 = 2.0 * std::numbers::pi * f2;
  out.mass = 2.0 * zeta * w1 * w2 / (w1 + w2);
  out.stiffness = 2.0 * zeta / (w1 + w2);
  return out;
}

}  // namespace catena::model::detail
