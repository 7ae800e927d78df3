#include "catena/solvers/time/step_matrices.hpp"

#include "catena/assembly/compact_matrix.hpp"
#include "catena/assembly/petsc_call.hpp"
#include "catena/solvers/newton/constraints_last_ordering.hpp"

namespace catena::solvers {

StepMatrices::StepMatrices(assembly::SecondOrderSystem& s, Vec q) : system(s) {
  tangent_q = system.create_vector();
  tangent_v = system.create_vector();
  // Only the matrices this system uses: each holds the full pattern from the start.
  mass = system.create_matrix();
  K = system.create_matrix();
  if (system.has_damping()) C = system.create_matrix();
  system.jacobian({q, nullptr, {}}, {0.0, 0.0, 1.0}, mass.get());
  mass_product = assembly::compact_copy(mass.get());
  CATENA_PETSC(MatDuplicate(mass.get(), MAT_COPY_VALUES, jacobian.out()));
  algebraic = std::make_unique<AlgebraicPart>(system, mass.get());
  if (algebraic->active()) {
    mark_constraint_rows(jacobian.get(), algebraic->mask());
    coupling = system.create_matrix();
    system.jacobian({q, nullptr, {}}, {0.0, 0.0, 0.0, 1.0, 0.0}, coupling.get());
  }
}

void StepMatrices::evaluate_tangent(Vec q, Vec v, double t) {
  if (q != tangent_q.get()) {
    CATENA_PETSC(VecCopy(q, tangent_q.get()));
    CATENA_PETSC(VecCopy(v, tangent_v.get()));
  }
  tangent_t = t;
  system.tangent_parts({tangent_q.get(), tangent_v.get(), {}, t}, K.get(), damping_matrix());
  // Gᵀ where K is, and at its velocity: a slider's Coulomb friction puts μ φ(ṡ) ∂n/∂λ into
  // its multiplier columns.
  if (algebraic->active() && !system.constraints_linear())
    system.constraint_jacobian({tangent_q.get(), tangent_v.get(), {}, t}, {0.0, 0.0, 0.0, 1.0, 0.0},
                               coupling.get());
  round_off.set_tangent(K.get());
}

std::unique_ptr<ReusableNewton> StepMatrices::make_newton(
    const std::string& prefix, int max_iterations, bool full_newton, Vec residual,
    ReusableNewton::Residual f, ReusableNewton::MatrixBuilder build) const {
  NewtonSettings settings;
  settings.max_iterations = max_iterations;
  settings.full_newton = full_newton;
  settings.pivoting = pivoting();
  return std::make_unique<ReusableNewton>(system.comm(), jacobian.get(), residual, prefix,
                                          JacobianSymmetry::general, settings, std::move(f),
                                          std::move(build));
}

void StepMatrices::save_tangent(ResumeState& out, const std::string& prefix) const {
  out.vectors[prefix + ".tangent_q"] = tangent_q.get();
  out.vectors[prefix + ".tangent_v"] = tangent_v.get();
  out.reals[prefix + ".tangent_t"] = tangent_t;
  out.integers[prefix + ".round_off_known"] = round_off.known() ? 1 : 0;
}

bool StepMatrices::restore_tangent(const ResumeState& in, const std::string& prefix) {
  if (in.integer(prefix + ".round_off_known") == 0) return false;
  evaluate_tangent(in.vector(prefix + ".tangent_q"), in.vector(prefix + ".tangent_v"),
                   in.real(prefix + ".tangent_t"));
  return true;
}

}  // namespace catena::solvers
