#include "catena/solvers/hht_integrator.hpp"

#include <petscsnes.h>

#include <sstream>

#include "catena/assembly/petsc_call.hpp"
#include "catena/core/error.hpp"
#include "catena/solvers/direct_newton.hpp"
#include "catena/solvers/mumps_status.hpp"

namespace catena::solvers {

struct HhtIntegrator::Impl {
  assembly::SecondOrderSystem& system;
  HhtOptions options;
  double beta, gamma;
  double t = 0.0;
  VecHandle q0, v0, a0, f0;  // state at the start of the step (f0 = f(q0, v0))
  VecHandle q1, v1;          // trial state built from the unknown a1
  VecHandle a1, residual, work;
  MatHandle mass, jacobian;
  SnesHandle snes;
  CallbackGuard guard;

  Impl(assembly::SecondOrderSystem& s, const HhtOptions& o)
      : system(s), options(o), beta(0.25 * (1 - o.alpha) * (1 - o.alpha)), gamma(0.5 - o.alpha) {}

  // q1, v1 from a1 (Newmark).
  void kinematics(Vec a) {
    const double h = options.dt;
    CATENA_PETSC(VecCopy(q0.get(), q1.get()));
    CATENA_PETSC(VecAXPY(q1.get(), h, v0.get()));
    CATENA_PETSC(VecAXPY(q1.get(), h * h * (0.5 - beta), a0.get()));
    CATENA_PETSC(VecAXPY(q1.get(), h * h * beta, a));
    CATENA_PETSC(VecCopy(v0.get(), v1.get()));
    CATENA_PETSC(VecAXPY(v1.get(), h * (1 - gamma), a0.get()));
    CATENA_PETSC(VecAXPY(v1.get(), h * gamma, a));
  }

  // R(a1) = M a1 + (1 + α) f(q1, v1) − α f0.
  void residual_at(Vec a, Vec r) {
    kinematics(a);
    system.force({q1.get(), v1.get(), {}}, work.get());
    CATENA_PETSC(MatMult(mass.get(), a, r));
    CATENA_PETSC(VecAXPY(r, 1.0 + options.alpha, work.get()));
    CATENA_PETSC(VecAXPY(r, -options.alpha, f0.get()));
  }

  static PetscErrorCode form_function(SNES, Vec a, Vec r, void* ctx) {
    auto* self = static_cast<Impl*>(ctx);
    return self->guard.run([&] { self->residual_at(a, r); });
  }
  static PetscErrorCode form_jacobian(SNES, Vec a, Mat J, Mat, void* ctx) {
    auto* self = static_cast<Impl*>(ctx);
    return self->guard.run([&] {
      self->kinematics(a);
      const double h = self->options.dt, s = 1.0 + self->options.alpha;
      self->system.jacobian({self->q1.get(), self->v1.get(), {}},
                            {s * self->beta * h * h, s * self->gamma * h, 1.0}, J);
    });
  }
};

HhtIntegrator::HhtIntegrator(assembly::SecondOrderSystem& system, const HhtOptions& options) {
  if (!(options.alpha >= -1.0 / 3.0 && options.alpha <= 0.0))
    throw InputError({"", 0, "integrator.alpha"},
                     "HHT alpha = " + std::to_string(options.alpha) +
                         " is outside the accepted range [-1/3, 0]");
  if (!(options.dt > 0.0))
    throw InputError({"", 0, "integrator.dt"},
                     "time step " + std::to_string(options.dt) + " s must be positive");
  impl_ = std::make_unique<Impl>(system, options);
  Impl& s = *impl_;
  for (VecHandle* v : {&s.q0, &s.v0, &s.a0, &s.f0, &s.q1, &s.v1, &s.a1, &s.residual, &s.work})
    *v = system.create_vector();
  // The mass matrix is constant (ANCF): assemble it once.
  s.mass = system.create_matrix();
  s.jacobian = system.create_matrix();
  CATENA_PETSC(SNESCreate(system.comm(), s.snes.out()));
  CATENA_PETSC(SNESSetFunction(s.snes.get(), s.residual.get(), Impl::form_function, &s));
  CATENA_PETSC(SNESSetJacobian(s.snes.get(), s.jacobian.get(), s.jacobian.get(),
                               Impl::form_jacobian, &s));
  // Damping makes the Jacobian non-symmetric in general.
  configure_direct_newton(s.snes.get(), "hht_", JacobianSymmetry::general);
}

HhtIntegrator::~HhtIntegrator() = default;

void HhtIntegrator::initialize(double t, Vec q, Vec v) {
  Impl& s = *impl_;
  s.t = t;
  CATENA_PETSC(VecCopy(q, s.q0.get()));
  CATENA_PETSC(VecCopy(v, s.v0.get()));
  s.system.jacobian({s.q0.get(), s.v0.get(), {}}, {0.0, 0.0, 1.0}, s.mass.get());
  s.system.force({s.q0.get(), s.v0.get(), {}}, s.f0.get());
  // Consistent initial acceleration: M a0 = −f(q0, v0).
  KspHandle ksp = create_direct_ksp(s.system.comm(), "hht_mass_", JacobianSymmetry::symmetric);
  CATENA_PETSC(KSPSetOperators(ksp.get(), s.mass.get(), s.mass.get()));
  CATENA_PETSC(VecScale(s.f0.get(), -1.0));
  CATENA_PETSC(KSPSolve(ksp.get(), s.f0.get(), s.a0.get()));
  CATENA_PETSC(VecScale(s.f0.get(), -1.0));
  const MumpsStatus mumps = mumps_status(ksp.get());
  if (mumps.null_pivots > 0 || mumps.infog1 < 0)
    throw NumericalError(
        "HHT: the mass matrix is singular (" + std::to_string(mumps.null_pivots) +
        " null pivots, MUMPS INFOG(1) = " + std::to_string(mumps.infog1) +
        "): every free DOF needs mass; massless nodes (e.g. joined only by massless bars "
        "or springs) need a point mass");
  KSPConvergedReason reason;
  CATENA_PETSC(KSPGetConvergedReason(ksp.get(), &reason));
  if (reason < 0) throw NumericalError("HHT: the initial acceleration solve failed");
}

HhtStepReport HhtIntegrator::step() {
  Impl& s = *impl_;
  // Scale of f's round-off for the convergence test (see StaticSolver).
  const double scale = s.system.element_force_norm({s.q0.get(), s.v0.get(), {}});
  CATENA_PETSC(SNESSetTolerances(s.snes.get(), s.options.atol + s.options.rtol * scale,
                                 s.options.rtol, kNewtonStepTolerance,
                                 s.options.max_newton_iterations, 100000));
  CATENA_PETSC(VecCopy(s.a0.get(), s.a1.get()));  // predictor: constant acceleration
  const PetscErrorCode ierr = SNESSolve(s.snes.get(), nullptr, s.a1.get());
  s.guard.rethrow_if_any();
  CATENA_PETSC(ierr);
  SNESConvergedReason reason;
  PetscInt its = 0;
  CATENA_PETSC(SNESGetConvergedReason(s.snes.get(), &reason));
  CATENA_PETSC(SNESGetIterationNumber(s.snes.get(), &its));
  KSP ksp = nullptr;
  CATENA_PETSC(SNESGetKSP(s.snes.get(), &ksp));
  const MumpsStatus mumps = its > 0 ? mumps_status(ksp) : MumpsStatus{};
  if (mumps.infog1 < 0 || mumps.null_pivots > 0 || reason <= 0) {
    std::ostringstream os;
    os << "HHT step from t = " << s.t << " s with h = " << s.options.dt
       << " s did not converge (SNES reason " << static_cast<int>(reason) << ", " << its
       << " iterations, MUMPS INFOG(1) = " << mumps.infog1 << ", null pivots "
       << mumps.null_pivots << ")";
    throw NumericalError(os.str());
  }
  HhtStepReport report;
  report.newton_iterations = static_cast<int>(its);
  PetscReal norm = 0.0;
  CATENA_PETSC(SNESGetFunctionNorm(s.snes.get(), &norm));
  report.residual_norm = norm;
  // Accept: the new state becomes the start of the next step.
  s.kinematics(s.a1.get());
  CATENA_PETSC(VecCopy(s.q1.get(), s.q0.get()));
  CATENA_PETSC(VecCopy(s.v1.get(), s.v0.get()));
  CATENA_PETSC(VecCopy(s.a1.get(), s.a0.get()));
  s.system.force({s.q0.get(), s.v0.get(), {}}, s.f0.get());
  s.t += s.options.dt;
  return report;
}

double HhtIntegrator::time() const { return impl_->t; }
Vec HhtIntegrator::q() const { return impl_->q0.get(); }
Vec HhtIntegrator::v() const { return impl_->v0.get(); }
Vec HhtIntegrator::a() const { return impl_->a0.get(); }
double HhtIntegrator::spectral_radius_at_infinity() const {
  return (1.0 + impl_->options.alpha) / (1.0 - impl_->options.alpha);
}

}  // namespace catena::solvers
