#pragma once
// What PetscTsIntegrator needs to know about a PETSc TS type that TS does not report:
// whether the bridge supports it, its classical order (for step doubling's Richardson
// estimate), whether it keeps a history between steps that a restart would lose, and
// whose dense output to use.
//
//   type          order                               history  dense output
//   alpha2        2                                   A₀       Hermite (own a)
//   alpha         2 (first-order generalised-α)       U̇₀       Hermite
//   bdf           -ts_bdf_order k (default 2)         yes      TSInterpolate
//   beuler, cn,   2 if θ = ½ (cn, midpoint), else 1   no       Hermite
//   theta
//   rosw          by -ts_rosw_type (table in .cpp)    no       TSInterpolate for ra34pw2,
//                                                              else Hermite
// (If TSInterpolate ever fails, Hermite takes over for the rest of the run.)
// theta's TSInterpolate extrapolates linearly from the step end with one derivative, a
// first-order dense output below cubic Hermite's, so it is not used; alpha2 has none.
//
// Refused (InputError): arkimex — its explicit first stages take U̇ = −F(t, U, 0), i.e.
// assume F = U̇ + G(t, U) (identity mass); with M v̇ in F they are wrong (measured: no
// convergence on the oscillator); irk — its stage matrix is a MATKAIJ, which MUMPS cannot
// factor; rosw tableaus with explicit stages (assp3p3s1c, lassp3p4s2c, llssp3p4s2c, ark3)
// — the same identity-mass assumption (measured: divergence); explicit types (euler, rk,
// ssp, ...) — with only an IFunction PETSc's right-hand side is silently zero; every
// other type is untested.
#include <petscts.h>

#include <string>

namespace catena::solvers::detail {

enum class TsDenseOutput { hermite, ts_interpolate };

struct TsMethodTraits {
  bool supported = false;
  std::string refusal;  // why not, when !supported
  int order = 1;
  bool keeps_history = false;  // rejected steps are rolled back (TSRollBack), not restarted
  TsDenseOutput dense = TsDenseOutput::hermite;
};

// Logically collective on ts (the type must be set).
TsMethodTraits ts_method_traits(TS ts);

// The types ts_method_traits supports, for messages.
inline constexpr const char* kSupportedTsTypes =
    "alpha2 (default), alpha, bdf, beuler, cn, theta, rosw";

}  // namespace catena::solvers::detail
