#pragma once
// A small dense static solver for element-level regression tests (tests only; production
// statics go through assembly + SNES). Element-agnostic: it sees kernels only through the
// Element contract (element.hpp).
//
// Global DOFs are node-major: node n owns dofs_per_node[n] consecutive DOFs starting at
// dof_offset(n); an element uses the first element->dofs_per_node() of each of its nodes
// (the nodal layout [r, r_x, r_y, r_z] is shared, so a 6-DOF cable and a 12-DOF beam may
// meet at a 12-DOF node). Fixed DOFs keep their q0 value and are eliminated.
//
// Solves  R(q, λ) = Σ_e f_e(q; λ) − λ F = 0  for λ: 0 → 1, where f_e includes the element's
// own loads (evaluated at LoadPath(λ): gravity and distributed loads scaled by λ,
// prestrain in place) and F the dead nodal and generalized DOF loads. Newton with the analytic K
// (Eigen dense LU) in each load step; a failed step (no convergence in max_newton_iterations,
// non-finite residual) is retried with half the increment, a converged one doubles it (up to
// initial_step). Convergence of a step: ‖R_free‖₂ ≤ atol + rtol·scale (scale: ‖external load on
// free DOFs at λ = 1‖₂, or the first residual if that is zero), or a Newton update with ‖Δq‖_∞ ≤
// stol·max(1, ‖q‖_∞) (stiff axial terms put a round-off floor on ‖R‖).
#include <vector>

#include "catena/core/vec3.hpp"
#include "catena/elements/element.hpp"

namespace catena::test {

struct DenseElement {
  const elements::Element* element = nullptr;  // not owned; must outlive the solve
  std::vector<int> nodes;                      // global node indices, in element order
};

struct NodalForce {
  int node = 0;
  Vec3 force = Vec3::Zero();  // N, dead, on the node's position DOFs
};

struct DofLoad {
  int dof = 0;         // global DOF index
  double value = 0.0;  // dead generalized force (N on positions, N·m on gradients)
};

struct DenseStaticsProblem {
  std::vector<DenseElement> elements;
  std::vector<int> dofs_per_node;  // per global node
  std::vector<double> q0;          // initial state; fixed DOFs keep these values
  std::vector<int> fixed_dofs;     // global DOF indices
  std::vector<NodalForce> nodal_forces;
  std::vector<DofLoad> dof_loads;
};

struct DenseStaticsOptions {
  double initial_step = 1.0;       // first (and largest) load increment
  double min_step = 1e-6;          // give up below this increment
  int max_load_steps = 500;        // accepted + rejected
  int max_newton_iterations = 50;  // stiff axial terms make early iterations erratic
  double rtol = 1e-10;
  double atol = 0.0;  // N
  double stol = 1e-12;
};

struct DenseStaticsResult {
  bool converged = false;
  std::vector<double> q;     // the last converged state
  double load_factor = 0.0;  // reached (1 when converged)
  int n_load_steps = 0;      // accepted
  int n_rejected_steps = 0;
  int n_newton_iterations = 0;  // total, including rejected steps
  double residual_norm = 0.0;   // ‖R_free‖₂ at the end
};

// First global DOF of `node`.
int dof_offset(const DenseStaticsProblem& p, int node);
int n_global_dofs(const DenseStaticsProblem& p);

// R(q, λ) (full length) and, if K is non-null, the dense row-major ∂R/∂q.
std::vector<double> assemble_residual(const DenseStaticsProblem& p, const std::vector<double>& q,
                                      double load_factor, std::vector<double>* K = nullptr);

DenseStaticsResult solve_dense_statics(const DenseStaticsProblem& p,
                                       const DenseStaticsOptions& options = {});

}  // namespace catena::test
