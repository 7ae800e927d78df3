#include "lagrange_top.hpp"

#include <algorithm>

#include "catena/assembly/petsc_call.hpp"

namespace catena::test {

BodyState body_state(const assembly::SecondOrderSystem& system, Vec q, Vec v) {
  const auto& dofs = system.dof_map();
  double values[2][12] = {};
  PetscInt lo = 0, hi = 0;
  CATENA_PETSC(VecGetOwnershipRange(q, &lo, &hi));
  for (int k = 0; k < 12; ++k) {
    const PetscInt g = dofs.global_dof(0, k);
    if (g >= lo && g < hi) {
      CATENA_PETSC(VecGetValues(q, 1, &g, &values[0][k]));
      CATENA_PETSC(VecGetValues(v, 1, &g, &values[1][k]));
    }
  }
  MPI_Allreduce(MPI_IN_PLACE, values, 24, MPI_DOUBLE, MPI_SUM, system.comm());
  BodyState s;
  const Vec3 origin = system.model().nodes[0].position;
  for (int d = 0; d < 3; ++d) {
    // A fixed DOF has no global index: it keeps its reference value (the origin), at rest.
    s.r[d] = dofs.global_dof(0, d) >= 0 ? values[0][d] : origin[d];
    s.r_dot[d] = dofs.global_dof(0, d) >= 0 ? values[1][d] : 0.0;
    for (int a = 0; a < 3; ++a) {
      s.e[a][d] = values[0][3 + 3 * a + d];
      s.e_dot[a][d] = values[1][3 + 3 * a + d];
    }
  }
  return s;
}

Invariants invariants(const Top& top, const BodyState& s) {
  Mat3 R;
  for (int a = 0; a < 3; ++a) R.col(a) = s.e[a];
  Vec3 omega = Vec3::Zero();
  for (int a = 0; a < 3; ++a) omega += 0.5 * s.e[a].cross(s.e_dot[a]);
  const Mat3 inertia_pivot =
      Vec3(top.transverse_at_pivot(), top.transverse_at_pivot(), top.I3).asDiagonal();
  const Vec3 L = R * inertia_pivot * R.transpose() * omega;
  const double height = top.l * s.e[2][2];
  Invariants out;
  out.energy = 0.5 * omega.dot(L) + top.m * top.g * height;
  out.vertical_momentum = L[2];
  out.nutation = std::acos(std::clamp(s.e[2][2], -1.0, 1.0));
  out.precession_angle = std::atan2(s.e[2][1], s.e[2][0]);
  out.frame_error = (R.transpose() * R - Mat3::Identity()).cwiseAbs().maxCoeff();
  return out;
}

void set_top_velocity(const assembly::SecondOrderSystem& system, const Top& top, Vec v) {
  const auto& dofs = system.dof_map();
  const Vec3 w = top.angular_velocity();
  for (int a = 0; a < 3; ++a) {
    Vec3 e = Vec3::Zero();
    e = a == 0 ? top.e1() : a == 1 ? Vec3::UnitY() : top.e3();
    const Vec3 rate = w.cross(e);
    for (int d = 0; d < 3; ++d) {
      const PetscInt g = dofs.global_dof(0, 3 + 3 * a + d);
      PetscInt lo = 0, hi = 0;
      CATENA_PETSC(VecGetOwnershipRange(v, &lo, &hi));
      if (g >= lo && g < hi) CATENA_PETSC(VecSetValue(v, g, rate[d], INSERT_VALUES));
    }
  }
  CATENA_PETSC(VecAssemblyBegin(v));
  CATENA_PETSC(VecAssemblyEnd(v));
}

}  // namespace catena::test
