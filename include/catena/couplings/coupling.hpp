#pragma once
// The one contract for everything that adds to the residual
//
//   R(t, q, v, a, λ) = M a + f(t, q, v; λ_path) + Gᵀλ ,   g(q, t) = 0
//
// (assembly/second_order_system.hpp): elements and one-node kernels, moving loads,
// pantograph contacts, constraints — and what comes next. A coupling names the unknowns it
// may act on (DofKey: independent of how they are numbered or distributed), says which
// pairs of them its matrix may couple, which of them it acts on at time t, and evaluates
// its part of f and of the Newton matrix on those alone. It never sees PETSc, ranks or
// global vectors (this layer does not link them): SecondOrderSystem gathers the values,
// calls evaluate() and scatters the result, the same loop for every kind.
//
// Adding a kind of coupling: a class here (one header, one source, unit tests with
// finite-difference Jacobians) and one line in model_couplings.cpp where the model's
// description becomes couplings (docs/architecture.md, "How to add ...").
#include <cstdint>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "catena/elements/element.hpp"

namespace catena::couplings {

// An unknown by what it is: nodal DOF `component` (0..11 in the layout [r, r_x, r_y, r_z])
// of model node `index`, or multiplier `component` (0..2) of model constraint `index`.
// A nodal DOF that is fixed (a support) or that the node does not carry has its
// reference value and no row.
struct DofKey {
  enum class Kind : std::uint8_t { node, multiplier };
  Kind kind = Kind::node;
  int index = 0;
  int component = 0;

  static DofKey node(int node_index, int k) { return {Kind::node, node_index, k}; }
  static DofKey multiplier(int constraint, int k) { return {Kind::multiplier, constraint, k}; }
};

// The parts of the Newton matrix J = c_K K + c_C C + c_M M + c_λ Gᵀ + c_g G:
//   K = ∂f/∂q, C = ∂f/∂v, M the mass, Gᵀ = ∂(Gᵀλ)/∂λ (nodal rows, multiplier columns),
//   G = ∂g/∂q (multiplier rows, nodal columns).
struct JacobianCoefficients {
  double c_K = 1.0;
  double c_C = 0.0;
  double c_M = 0.0;
  double c_lambda = 0.0;
  double c_g = 0.0;
};
// Statics: J = ∂f/∂q + Gᵀ + G (symmetric).
inline constexpr JacobianCoefficients kStaticJacobian{1.0, 0.0, 0.0, 1.0, 1.0};

// Where a coupling is evaluated: the values of its active DOFs (active_dofs() order).
struct CouplingState {
  std::span<const double> q;
  std::span<const double> v;  // empty: zero velocity (statics)
  elements::LoadPath path;    // the static load path; dynamics runs at its end
  double t = 0.0;             // s
};

// One combination of the matrix parts, written (not added) into `out`: n_active², row-major.
struct MatrixRequest {
  JacobianCoefficients c;
  double* out = nullptr;
};

// Caller-owned buffers a coupling may use during evaluate() (it sizes them).
struct Scratch {
  std::vector<double> a, b, c, d;
};

// How local patches (assembly/local_patch.hpp) treat a coupling.
enum class PatchRole {
  kernel,             // a fixed set of DOFs: part of any patch that reaches them
  at_patch_time,      // acts on active_dofs(t): part of a patch at its time t
  state_independent,  // its force does not depend on q or v: it cancels in a patch's change
  excluded,           // its forces are not re-evaluated in patches: its nodes are not unknowns
};

// The values of a coupling's DOFs in the state being evaluated, by position in dofs(): what
// a coupling whose active DOFs follow its own unknowns reads to choose them
// (Coupling::active_dofs_at; a slider's arc length picks the path element it acts on).
class DofValues {
 public:
  virtual double at(int position) const = 0;

 protected:
  ~DofValues() = default;
};

class Coupling {
 public:
  virtual ~Coupling() = default;
  Coupling() = default;
  Coupling(const Coupling&) = delete;
  Coupling& operator=(const Coupling&) = delete;

  // Every unknown it may act on, in its own order (fixed for its lifetime).
  const std::vector<DofKey>& dofs() const { return dofs_; }

  // The pairs (row, column) of positions in dofs() its matrix may ever be nonzero at: the
  // system's matrix pattern is the union of these. Dense couplings: every pair.
  virtual bool dense() const { return true; }
  virtual void pattern(std::vector<std::pair<int, int>>& entries) const;

  // True if it acts on all of dofs() at every time, in that order; otherwise
  // active_dofs() says on which (and in which order evaluate() sees them).
  virtual bool acts_on_all() const { return true; }
  // Positions in dofs() of the DOFs it acts on at time t; empty: none now. The matrix
  // entries among them lie in pattern().
  virtual void active_dofs(double t, std::vector<int>& positions) const;
  // The same where they also depend on the state (state_dependent_activity()); `q` holds
  // the state being evaluated. By default: active_dofs(t).
  virtual bool state_dependent_activity() const { return false; }
  virtual void active_dofs_at(double t, const DofValues& q, std::vector<int>& positions) const;

  // f (n_active, may be null) and each requested matrix combination over the active DOFs.
  // Overwrites the outputs.
  virtual void evaluate(const CouplingState& s, double* f, std::span<const MatrixRequest> m,
                        Scratch& scratch) const = 0;

  // False if ∂f/∂v is zero at every state.
  virtual bool has_damping() const { return false; }
  // Whether |f| of this coupling enters the round-off scale of the residual (the element
  // forces; see SecondOrderSystem::element_force_norm).
  virtual bool in_force_scale() const { return false; }
  virtual PatchRole patch_role() const = 0;

 protected:
  std::vector<DofKey> dofs_;
};

using CouplingList = std::vector<std::unique_ptr<Coupling>>;

}  // namespace catena::couplings
