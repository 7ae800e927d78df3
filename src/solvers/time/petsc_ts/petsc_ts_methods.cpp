#include "petsc_ts_methods.hpp"

#include <cstring>

#include "catena/assembly/petsc_call.hpp"

namespace catena::solvers::detail {
namespace {

// PETSc 3.18's Rosenbrock-W tableaus (petscts.h; rosw.c cites Rang & Angermann, Sandu et
// al., Hairer & Wanner, Shampine, van Veldhuizen): classical order, whether the bridge
// runs it, and whether its TSInterpolate is worth using. Measured on the oscillator
// (h = 0.01, 20 steps): the tableaus with explicit stages (zero diagonal γ: assp3p3s1c,
// lassp3p4s2c, llssp3p4s2c, ark3) assume an identity mass like arkimex and diverge (to
// 1e41 m) or miss by 1e-2 m; the interpolants of 2m, 2p, sandu3 miss the step end (by
// 3.9e-4, 3.9e-4, 4.8e-6 m), ten times the method's own error for 2m; ra34pw2's meets
// it to 1e-17 m and is more accurate inside the step than at its end. The others have no
// interpolant.
struct RosWTableau {
  const char* name;
  int order;
  bool supported;
  bool interpolant;
};
constexpr RosWTableau kRosW[] = {{"theta1", 1, true, false},       {"theta2", 2, true, false},
                                 {"2m", 2, true, false},           {"2p", 2, true, false},
                                 {"ra3pw", 3, true, false},        {"ra34pw2", 3, true, true},
                                 {"rodas3", 3, true, false},       {"sandu3", 3, true, false},
                                 {"assp3p3s1c", 3, false, false},  {"lassp3p4s2c", 3, false, false},
                                 {"llssp3p4s2c", 3, false, false}, {"ark3", 3, false, false},
                                 {"grk4t", 4, true, false},        {"shamp4", 4, true, false},
                                 {"veldd4", 4, true, false},       {"4l", 4, true, false}};

const RosWTableau* find_rosw(const char* name) {
  for (const RosWTableau& t : kRosW)
    if (name && std::strcmp(t.name, name) == 0) return &t;
  return nullptr;
}

}  // namespace

TsMethodTraits ts_method_traits(TS ts) {
  TSType type_name = nullptr;
  CATENA_PETSC(TSGetType(ts, &type_name));
  const std::string type = type_name ? type_name : "";
  TsMethodTraits m;
  m.supported = true;
  if (type == TSALPHA2 || type == TSALPHA) {
    m.order = 2;
    m.keeps_history = true;  // the derivative (A₀, U̇₀) carried from step to step
  } else if (type == TSBDF) {
    PetscInt order = 2;
    CATENA_PETSC(TSBDFGetOrder(ts, &order));
    m.order = static_cast<int>(order);
    m.keeps_history = true;
    m.dense = TsDenseOutput::ts_interpolate;
  } else if (type == TSTHETA || type == TSBEULER || type == TSCN) {
    PetscReal theta = 1.0;
    CATENA_PETSC(TSThetaGetTheta(ts, &theta));
    m.order = theta == 0.5 ? 2 : 1;
  } else if (type == TSROSW) {
    TSRosWType rosw = nullptr;
    CATENA_PETSC(TSRosWGetType(ts, &rosw));
    const RosWTableau* t = find_rosw(rosw);
    if (!t || !t->supported) {
      m.supported = false;
      m.refusal = "rosw tableau '" + std::string(rosw ? rosw : "") +
                  (t ? "' has explicit stages, which assume an identity mass matrix"
                     : "' is untested with the bridge");
    } else {
      m.order = t->order;
      if (t->interpolant) m.dense = TsDenseOutput::ts_interpolate;
    }
  } else {
    m.supported = false;
    if (type == TSARKIMEX)
      m.refusal = "its explicit stages assume an identity mass matrix (F = U' + G(t, U))";
    else if (type == TSIRK)
      m.refusal = "its stage matrix (MATKAIJ) cannot be factored by MUMPS";
    else
      m.refusal = "it is explicit or untested with the bridge's implicit form";
  }
  return m;
}

}  // namespace catena::solvers::detail
