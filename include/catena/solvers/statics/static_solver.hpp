#pragma once
// Static equilibrium f(q) = 0 by Newton's method (PETSc SNES newtonls with full steps, no
// line search: direct_newton.hpp) with a direct solve (KSPPREONLY + MUMPS LDLᵀ, the tangent
// being symmetric), continued along the load path of elements::LoadPath from the
// stress-free reference configuration: tension the cables, put on gravity and loads,
// release cable prestrain to its scene value. The step along the path halves when Newton
// fails or converges to an unstable equilibrium (negative pivots in the LDLᵀ factorisation)
// and doubles when Newton converges quickly.
// Every SNES convergence reason and MUMPS's status are checked.
//
// Options database prefix: -static_ (e.g. -static_snes_monitor, -static_ksp_type gmres,
// -static_pc_type, -static_mat_mumps_icntl_14 50). Set last, so the command line wins.
#include <functional>
#include <memory>
#include <string>

#include "catena/assembly/second_order_system.hpp"
#include "catena/model/model.hpp"

namespace catena::solvers {

// What became of a starting guess (StaticSolver::solve's `guess`).
enum class GuessOutcome { none, accepted, rejected };

struct StaticReport {
  double load_factor = 0.0;  // reached (1 on success)
  int n_load_steps = 0;      // accepted
  int n_rejected_steps = 0;
  int n_unstable_rejections = 0;  // rejected because the equilibrium was unstable
  int n_newton_iterations = 0;    // over all attempts
  double residual_norm = 0.0;     // 2-norm of f at the returned state, N
  GuessOutcome guess = GuessOutcome::none;
};

// Where a static solve is, after a load-step attempt (for progress output).
struct StaticProgress {
  std::string where;            // the load path's point reached, in words
  int n_load_steps = 0;         // accepted so far
  int n_rejected_steps = 0;     // so far
  int n_newton_iterations = 0;  // so far, over all attempts
};

class StaticSolver {
 public:
  // Collective.
  StaticSolver(assembly::SecondOrderSystem& system, const model::StaticOptions& options);
  ~StaticSolver();
  StaticSolver(const StaticSolver&) = delete;
  StaticSolver& operator=(const StaticSolver&) = delete;

  // Collective. On entry q is the initial guess at λ = 0 (normally the reference state);
  // on return the equilibrium at λ = 1. Throws NumericalError naming the load level, the
  // residual norm and the node with the largest residual when load stepping gives up, or
  // when the stiffness matrix is singular (an under-supported structure). With `guess`
  // (a state near the equilibrium, e.g. hanging_cable_guess.hpp) Newton first tries the
  // whole load from it; only if that fails or ends unstable does the path start from q.
  StaticReport solve(Vec q, Vec guess = nullptr);

  // Not collective. Called on every rank after each load-step attempt of solve().
  void on_progress(std::function<void(const StaticProgress&)> callback);

 private:
  struct Attempt {
    bool accepted = false;  // converged to a stable equilibrium
    bool unstable = false;  // converged, to an unstable equilibrium
    int iterations = 0;
  };
  Attempt attempt(double target, double tau_end, Vec start, Vec trial, StaticReport& report);
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace catena::solvers
