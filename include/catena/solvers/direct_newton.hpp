#pragma once
// The Newton configuration shared by Catena's nonlinear solvers (statics, HHT, IRK stages):
// SNES newtonls with full steps (a residual-norm line search rejects good steps in stiff
// axial/bending problems; callers cut the load or time step instead), no divergence
// tolerance, KSPPREONLY with a MUMPS factorisation (LDLᵀ when the Jacobian is symmetric,
// else LU) with null-pivot detection, options prefix `prefix`, SNESSetFromOptions last.
#include <petscsnes.h>

#include <string>

#include "catena/assembly/petsc_handle.hpp"

namespace catena::solvers {

enum class JacobianSymmetry { symmetric, general };

// Logically collective on the SNES.
void configure_direct_newton(SNES snes, const std::string& prefix, JacobianSymmetry symmetry);

// Collective. A KSPPREONLY + MUMPS factorisation (LDLᵀ or LU) with null-pivot detection
// and options prefix `prefix`, KSPSetFromOptions applied. Set further MUMPS defaults
// (e.g. enable_mumps_exact_inertia) before calling.
KspHandle create_direct_ksp(MPI_Comm comm, const std::string& prefix, JacobianSymmetry symmetry);

// Relative Newton update at which an iterate is converged to round-off (SNES stol).
inline constexpr double kNewtonStepTolerance = 1e-12;

}  // namespace catena::solvers
