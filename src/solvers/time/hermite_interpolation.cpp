#include "catena/solvers/time/hermite_interpolation.hpp"

#include "catena/assembly/petsc_call.hpp"

namespace catena::solvers {

void hermite_interpolate(double theta, double h, Vec y0, Vec d0, Vec y1, Vec d1, Vec out) {
  const double t2 = theta * theta, t3 = t2 * theta;
  const double alpha[4] = {1.0 - 3.0 * t2 + 2.0 * t3, h * (theta - 2.0 * t2 + t3),
                           3.0 * t2 - 2.0 * t3, h * (t3 - t2)};
  Vec parts[4] = {y0, d0, y1, d1};
  CATENA_PETSC(VecSet(out, 0.0));
  CATENA_PETSC(VecMAXPY(out, 4, alpha, parts));
}

}  // namespace catena::solvers
