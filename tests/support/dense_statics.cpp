#include "dense_statics.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace catena::test {
namespace {

// Global DOF indices of an element's local DOFs (node-major).
std::vector<int> element_dofs(const DenseStaticsProblem& p, const DenseElement& e) {
  const int per_node = e.element->dofs_per_node();
  std::vector<int> dofs;
  dofs.reserve(static_cast<size_t>(e.element->n_dofs()));
  for (int node : e.nodes) {
    if (per_node > p.dofs_per_node.at(node))
      throw std::invalid_argument("dense_statics: element needs more DOFs than its node has");
    for (int k = 0; k < per_node; ++k) dofs.push_back(dof_offset(p, node) + k);
  }
  return dofs;
}

// Dead loads F (nodal forces and generalized DOF loads) at λ = 1.
std::vector<double> dead_loads(const DenseStaticsProblem& p) {
  std::vector<double> F(static_cast<size_t>(n_global_dofs(p)), 0.0);
  for (const NodalForce& l : p.nodal_forces)
    for (int c = 0; c < 3; ++c) F[dof_offset(p, l.node) + c] += l.force[c];
  for (const DofLoad& l : p.dof_loads) F.at(l.dof) += l.value;
  return F;
}

struct FreeSet {
  std::vector<int> free;  // global indices of free DOFs
};

FreeSet free_dofs(const DenseStaticsProblem& p) {
  std::vector<char> fixed(static_cast<size_t>(n_global_dofs(p)), 0);
  for (int d : p.fixed_dofs) fixed.at(d) = 1;
  FreeSet s;
  for (int i = 0; i < static_cast<int>(fixed.size()); ++i)
    if (!fixed[i]) s.free.push_back(i);
  return s;
}

double free_norm(const std::vector<double>& r, const FreeSet& s) {
  double sum = 0.0;
  for (int i : s.free) sum += r[i] * r[i];
  return std::sqrt(sum);
}

struct NewtonOutcome {
  bool converged = false;
  int iterations = 0;
  double residual_norm = 0.0;
};

// Newton at fixed λ from q (updated in place).
NewtonOutcome newton(const DenseStaticsProblem& p, const FreeSet& s, double lambda, double scale,
                     const DenseStaticsOptions& o, std::vector<double>& q) {
  const int n = n_global_dofs(p), m = static_cast<int>(s.free.size());
  std::vector<double> K;
  NewtonOutcome out;
  for (int it = 0;; ++it) {
    const std::vector<double> r = assemble_residual(p, q, lambda, &K);
    out.residual_norm = free_norm(r, s);
    if (!std::isfinite(out.residual_norm)) return out;
    if (scale <= 0.0) scale = out.residual_norm;
    if (out.residual_norm <= o.atol + o.rtol * scale) {
      out.converged = true;
      return out;
    }
    if (it == o.max_newton_iterations) return out;
    ++out.iterations;
    Eigen::MatrixXd K_ff(m, m);
    Eigen::VectorXd r_f(m);
    for (int i = 0; i < m; ++i) {
      r_f[i] = r[s.free[i]];
      for (int j = 0; j < m; ++j) K_ff(i, j) = K[static_cast<size_t>(s.free[i]) * n + s.free[j]];
    }
    const Eigen::VectorXd dq = K_ff.partialPivLu().solve(-r_f);
    if (!dq.allFinite()) return out;
    double q_max = 0.0;
    for (int i = 0; i < m; ++i) {
      q[s.free[i]] += dq[i];
      q_max = std::max(q_max, std::abs(q[s.free[i]]));
    }
    if (dq.lpNorm<Eigen::Infinity>() <= o.stol * std::max(1.0, q_max)) {
      out.residual_norm = free_norm(assemble_residual(p, q, lambda), s);
      out.converged = std::isfinite(out.residual_norm);
      return out;
    }
  }
}

}  // namespace

int dof_offset(const DenseStaticsProblem& p, int node) {
  int offset = 0;
  for (int n = 0; n < node; ++n) offset += p.dofs_per_node[n];
  return offset;
}

int n_global_dofs(const DenseStaticsProblem& p) {
  return dof_offset(p, static_cast<int>(p.dofs_per_node.size()));
}

std::vector<double> assemble_residual(const DenseStaticsProblem& p, const std::vector<double>& q,
                                      double load_factor, std::vector<double>* K) {
  const int n = n_global_dofs(p);
  if (static_cast<int>(q.size()) != n) throw std::invalid_argument("dense_statics: q size");
  std::vector<double> r = dead_loads(p);
  for (double& x : r) x *= -load_factor;
  if (K != nullptr) K->assign(static_cast<size_t>(n) * n, 0.0);
  std::vector<double> q_e, f_e, K_e;
  for (const DenseElement& e : p.elements) {
    const std::vector<int> dofs = element_dofs(p, e);
    const int m = static_cast<int>(dofs.size());
    q_e.resize(m);
    f_e.resize(m);
    K_e.resize(static_cast<size_t>(m) * m);
    for (int i = 0; i < m; ++i) q_e[i] = q[dofs[i]];
    e.element->evaluate({q_e, {}, elements::LoadPath(load_factor)}, {true, K != nullptr, false},
                        {f_e.data(), K != nullptr ? K_e.data() : nullptr, nullptr});
    for (int i = 0; i < m; ++i) {
      r[dofs[i]] += f_e[i];
      if (K != nullptr)
        for (int j = 0; j < m; ++j)
          (*K)[static_cast<size_t>(dofs[i]) * n + dofs[j]] += K_e[static_cast<size_t>(i) * m + j];
    }
  }
  return r;
}

DenseStaticsResult solve_dense_statics(const DenseStaticsProblem& p, const DenseStaticsOptions& o) {
  const FreeSet s = free_dofs(p);
  DenseStaticsResult result;
  result.q = p.q0;
  // Scale of the external load on the free DOFs: R(q0, 1) − R(q0, 0).
  const std::vector<double> r1 = assemble_residual(p, p.q0, 1.0);
  const std::vector<double> r0 = assemble_residual(p, p.q0, 0.0);
  double scale = 0.0;
  for (int i : s.free) scale += (r1[i] - r0[i]) * (r1[i] - r0[i]);
  scale = std::sqrt(scale);

  double lambda = 0.0, step = o.initial_step;
  while (lambda < 1.0) {
    if (result.n_load_steps + result.n_rejected_steps >= o.max_load_steps) break;
    const double target = std::min(1.0, lambda + step);
    std::vector<double> q = result.q;
    const NewtonOutcome n = newton(p, s, target, scale, o, q);
    result.n_newton_iterations += n.iterations;
    result.residual_norm = n.residual_norm;
    if (n.converged) {
      result.q = std::move(q);
      lambda = target;
      ++result.n_load_steps;
      step = std::min(2.0 * step, o.initial_step);
    } else {
      ++result.n_rejected_steps;
      step *= 0.5;
      if (step < o.min_step) break;
    }
  }
  result.load_factor = lambda;
  result.converged = lambda >= 1.0;
  if (!result.converged)
    result.residual_norm = free_norm(assemble_residual(p, result.q, lambda), s);
  return result;
}

}  // namespace catena::test
