#include "system_fd_jacobian.hpp"

#include "catena/assembly/petsc_call.hpp"
#include "fd_jacobian.hpp"

namespace catena::test {

std::vector<double> reference_unknowns(const assembly::SecondOrderSystem& system) {
  VecHandle q = system.create_vector();
  system.reference_state(q.get());
  PetscInt n = 0;
  CATENA_PETSC(VecGetSize(q.get(), &n));
  const PetscScalar* a = nullptr;
  CATENA_PETSC(VecGetArrayRead(q.get(), &a));
  std::vector<double> x(a, a + n);
  CATENA_PETSC(VecRestoreArrayRead(q.get(), &a));
  return x;
}

SystemJacobians system_jacobians(assembly::SecondOrderSystem& system, const std::vector<double>& x,
                                 double t) {
  VecHandle q = system.create_vector(), f = system.create_vector();
  PetscInt n = 0;
  CATENA_PETSC(VecGetSize(q.get(), &n));
  const auto set_state = [&](const std::vector<double>& values) {
    PetscScalar* a = nullptr;
    CATENA_PETSC(VecGetArray(q.get(), &a));
    for (PetscInt i = 0; i < n; ++i) a[i] = values[static_cast<size_t>(i)];
    CATENA_PETSC(VecRestoreArray(q.get(), &a));
  };
  const auto residual = [&](const std::vector<double>& values, std::vector<double>& out) {
    set_state(values);
    system.force({q.get(), nullptr, {}, t}, f.get());
    const PetscScalar* r = nullptr;
    CATENA_PETSC(VecGetArrayRead(f.get(), &r));
    out.assign(r, r + n);
    CATENA_PETSC(VecRestoreArrayRead(f.get(), &r));
  };
  SystemJacobians j;
  j.n = static_cast<int>(n);
  j.finite_difference = central_difference_jacobian(residual, x, j.n);
  set_state(x);
  MatHandle K = system.create_matrix();
  system.jacobian({q.get(), nullptr, {}, t}, assembly::kStaticJacobian, K.get());
  j.analytic.resize(static_cast<size_t>(n * n));
  std::vector<PetscInt> all(static_cast<size_t>(n));
  for (PetscInt i = 0; i < n; ++i) all[static_cast<size_t>(i)] = i;
  CATENA_PETSC(MatGetValues(K.get(), n, all.data(), n, all.data(), j.analytic.data()));
  return j;
}

}  // namespace catena::test
