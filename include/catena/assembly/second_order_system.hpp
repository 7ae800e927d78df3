#pragma once
// The distributed second-order system every solver and integrator sees:
//
//   R(t, q, v, a, λ) = M a + f(t, q, v; λ_path) + Gᵀλ ,   f = f_int + f_damp − λ_path f_ext(t)
//   g(q, t) = 0                                           (model::Constraint, G = ∂g/∂q)
//   J = c_K ∂f/∂q + c_C ∂f/∂v + c_M M + c_λ Gᵀ + c_g G
// f_ext(t) holds dead loads (gravity, nodal and distributed loads) and moving loads
// (model::MovingLoad), which depend on t but not on q, so they add nothing to J.
//
// over the free DOFs (supports eliminated; their values are the reference values) and the
// Lagrange multipliers of the constraints. One vector holds both: the multiplier slots of
// q hold λ (those of v and a are unused and kept zero), and the multiplier rows of a
// residual hold g(q, t), in metres. algebraic_mask() marks the multiplier slots, so
// integrators can treat them as the algebraic part of the DAE (docs/integrators.md).
// Node constraints are linear in q, so their G is constant; a rigid body's frame
// constraints are quadratic (couplings/body_frame_constraint.hpp): where the model has any,
// constraints_linear() is false and integrators re-evaluate Gᵀ with the tangent.
//
// Every term is a coupling (couplings/coupling.hpp): this class partitions the model,
// numbers the unknowns the couplings name, and runs the one gather–evaluate–scatter loop
// over them for residuals, matrices and local patches. What output and checkpoints ask of a
// state (node values, section results, reactions, contact states, node-indexed rows) is
// assembly/state_view.hpp.
#include <mpi.h>
#include <petscmat.h>

#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "catena/assembly/dof_map.hpp"
#include "catena/assembly/local_patch.hpp"
#include "catena/assembly/partition.hpp"
#include "catena/assembly/petsc_handle.hpp"
#include "catena/couplings/coupling.hpp"
#include "catena/elements/element.hpp"
#include "catena/model/model.hpp"

namespace catena::assembly {

// Where to evaluate: global vectors of free DOFs (v may be null: zero velocity).
struct EvalPoint {
  Vec q = nullptr;
  Vec v = nullptr;
  elements::LoadPath path;  // the static load path; dynamics uses its end
  double t = 0.0;           // s: time, for time-dependent loads (moving loads)
};

using couplings::JacobianCoefficients;
using couplings::kStaticJacobian;

class SecondOrderSystem {
 public:
  // Collective: partitions the model, builds this rank's couplings, numbers the DOFs. The
  // model must outlive the system, which reads it when asked (a temporary does not compile).
  SecondOrderSystem(MPI_Comm comm, const model::Model& model);
  SecondOrderSystem(MPI_Comm comm, model::Model&& model) = delete;
  SecondOrderSystem(const SecondOrderSystem&) = delete;  // dofs_ points into partition_
  SecondOrderSystem& operator=(const SecondOrderSystem&) = delete;

  MPI_Comm comm() const { return comm_; }
  const model::Model& model() const { return *model_; }
  const DofMap& dof_map() const { return dofs_; }

  // Collective. A ghosted vector laid out as the free DOFs.
  VecHandle create_vector() const;
  // Collective. An assembled MPIAIJ matrix holding the union of the couplings' patterns as
  // explicit zeros; inserting outside it is an error (MAT_NEW_NONZERO_ALLOCATION_ERR), so
  // assembly never mallocs, and every matrix from here has the same nonzero pattern
  // (MatAXPY with SAME_NONZERO_PATTERN).
  MatHandle create_matrix() const;
  // Collective. q at the reference configuration (positions and nodal frames).
  void reference_state(Vec q) const;

  // Collective. f(t, q, v; λ) + Gᵀλ into the nodal rows of f, g(q, t) into its multiplier
  // rows (global vector). If element_norm is given, it also
  // receives element_force_norm(p) from the same pass (one extra reduction).
  void force(const EvalPoint& p, Vec f, double* element_norm = nullptr);
  // Collective. Norm of the unassembled element forces, sqrt(Σ_e |f_e|²): the scale of
  // the round-off in f, against which convergence tolerances are set.
  double element_force_norm(const EvalPoint& p);
  // Collective. J = c_K K + c_C C + c_M M + c_λ Gᵀ + c_g G into J (zeroed first,
  // assembled on return). Every entry of the pattern is inserted, zero or not, so all
  // matrices from this call share one nonzero pattern (MatAXPY SAME_NONZERO_PATTERN).
  void jacobian(const EvalPoint& p, const JacobianCoefficients& c, Mat J);
  // Collective. The same over the constraint couplings alone (c_λ Gᵀ + c_g G, and c_K Σλ H
  // where they are nonlinear): what integrators re-assemble with each tangent where the
  // constraints are not linear, without a pass over the elements.
  void constraint_jacobian(const EvalPoint& p, const JacobianCoefficients& c, Mat J);
  // Collective. K = ∂f/∂q + G (G in the multiplier rows: ∂R/∂q of the whole residual)
  // and C = ∂f/∂v at p in one element pass (matrices from create_matrix(); either may be
  // null). For integrators that combine them with coefficients of their own; the
  // multiplier columns Gᵀ come from jacobian() with c_λ = 1, or constraint_jacobian() (at
  // the same point where the constraints are not linear). K holds the constraints' Σ λ_k H_k.
  void tangent_parts(const EvalPoint& p, Mat K, Mat C);

  // Local patches (local_patch.hpp; local_patch.cpp). Collective: finds which owned DOFs
  // a patch may change alone. Once, before the first local_patch().
  void prepare_local_patches();
  // Not collective. The patch around `seeds` (owned local indices) at time t: the DOFs
  // reached from them across `layers` kernels (a moving contact counts as one), those of
  // them a patch may change alone.
  LocalPatch local_patch(const std::vector<PetscInt>& seeds, int layers, double t = 0.0);
  // Not collective. Σ f_e(q, v) over the patch's kernels and contacts, per row (f_rows:
  // rows.size()), from the owned arrays of q and v (v may be null: zero velocity). Moving loads are
  // left out: they do not depend on the state, so they cancel in a change of the residual.
  void patch_force(const LocalPatch& patch, const double* q, const double* v, double* f_rows) const;
  // Not collective. Σ M_e d_e over the patch's kernels, per row, for d given per unknown.
  void patch_mass_product(const LocalPatch& patch, const double* d, double* out_rows) const;
  // Not collective. The unknowns' block of c_K K + c_C C + c_M M at (q, v) (owned arrays;
  // v may be null), kernels and contacts, as entries that repeat (sum them).
  std::vector<PatchEntry> patch_matrix(const LocalPatch& patch, const double* q, const double* v,
                                       const JacobianCoefficients& c) const;

  // Not collective (the same answer on every rank). False if C = ∂f/∂v is zero at every
  // state: no kernel and no contact damps. Integrators then leave C out of their Newton
  // matrix and pass C = null to tangent_parts, which halves a tangent refresh's assembly.
  bool has_damping() const { return has_damping_; }

  // Constraints (Lagrange multipliers).
  bool has_constraints() const { return !model_->constraints.empty(); }
  // Collective. 1 in the multiplier slots, 0 in the nodal ones.
  void algebraic_mask(Vec mask) const;
  // Not collective (the same answer on every rank). False if some constraint's G depends
  // on q or t (a rigid body's frame, a joint between bodies, a driven revolute joint): its
  // ConstraintCoupling::linear().
  bool constraints_linear() const { return constraints_linear_; }
  // Collective. γ(q, v, t) of the acceleration-level constraints G a = γ in the multiplier
  // slots, 0 in the others (couplings/constraint_coupling.hpp): a prescribed motion's
  // ∂²u/∂t², a quadratic constraint's −vᵀ H v. p.v null: at rest.
  void constraint_acceleration(const EvalPoint& p, Vec out) const;
  // Collective. β(t) of the velocity-level constraints G v = β in the multiplier slots, 0 in
  // the others: a prescribed motion's velocity.
  void constraint_velocity(const EvalPoint& p, Vec out) const;
  // Collective. The constraint couplings' part of force() alone, without a pass over the
  // elements: g(q, t) in the multiplier rows, Gᵀλ in the nodal ones (zero where q's
  // multiplier slots are). What a projection onto g = 0 iterates on.
  void constraint_residual(const EvalPoint& p, Vec out) const;

  // Collective. Replaces the element kernel of every model element for which
  // `linearize(element index)` is true by its linearisation about q0 (elements/
  // linearized.hpp): from then on its force is f0 + K0 Δq + C0 v and its matrices are
  // constant. Residuals and matrices then take those elements from one assembled block
  // (K, C, M and Σ f0 over the free DOFs: a sparse product per residual, a matrix sum per
  // Jacobian, instead of an evaluation per element); local patches and output queries
  // still evaluate them one by one. Once per system. Returns how many elements this rank
  // linearised.
  int linearize_elements(Vec q0, const std::function<bool(int)>& linearize);

  // Collective. Makes each absorbing end (model::AbsorbingEnd) pull as the line beyond it
  // would about q0, the run's initial state (v = 0, t = 0, the load path's end): with the
  // force that holds its node there (f at the node, the absorbing ends left out) and the
  // dashpot of its line's wave impedances (elements/absorbing_end.hpp). Until then they
  // do nothing. Throws NumericalError naming the node if its line is not in tension there.
  void calibrate_absorbing_ends(Vec q0);

  // Not collective (call on every rank alike). A moving window (model::CatenaryWindow) moved
  // the line's state back by `ds` m along the contact wire: every pantograph's contact
  // point moves back with it.
  void move_contacts_back(double ds);

  // Collective. The structure without its moving contacts and moving loads, linearised
  // about q0 (v = 0, t = 0, the end of the load path): K = ∂f/∂q, C = ∂f/∂v, M and
  // f0 = f(q0, 0) over every other coupling (elements, masses, supports, dead loads), so
  // that f ≈ f0 + K (q − q0) + C v. The modal model's matrices (solvers/modal). Before
  // linearize_elements (asserted).
  struct StructureMatrices {
    MatHandle K, C, M;
    VecHandle f0;
  };
  StructureMatrices structure_matrices(Vec q0);

  // True if the static load path needs its second phase (some cable's prestrain is below
  // the path's tensioning prestrain, see elements::LocalState).
  bool has_slack_prestrain() const;

  // A global DOF in words, for messages: "node 17 (y)" or "constraint 2 (multiplier y,
  // node 5)" (node ids as in the scene; constraints numbered from 1 in scene order).
  std::string describe_dof(PetscInt global) const;

 private:
  friend class StateView;  // evaluates couplings at a state for output (state_view.hpp)

  // Buffers of the evaluation loop, grown to the largest active set.
  struct Buffers {
    std::vector<int> positions;
    std::vector<PetscInt> local, global;
    std::vector<double> fixed, coefficient;
    std::vector<double> q, v, f, block, block2, scaled;
    couplings::Scratch scratch;
    std::vector<std::pair<int, int>> entries;
  };
  // The active DOFs of coupling i at time t: ghosted local indices (−1: fixed or absent),
  // global indices (−1: fixed or absent), the values used where fixed, and the slots'
  // coefficients (dof_map.hpp: nodal value = coefficient × unknown) or null when all are 1.
  // Couplings see nodal values: gather multiplies by the coefficients, and whatever adds a
  // coupling's force or matrix into unknowns' rows multiplies by them (scale_force,
  // scale_block).
  struct ActiveDofs {
    const PetscInt* local = nullptr;
    const PetscInt* global = nullptr;
    const double* fixed = nullptr;
    const double* coefficient = nullptr;
    size_t n = 0;
    // Position in the coupling's dofs() of each active DOF; null: all of them, in order.
    const int* positions = nullptr;
    size_t position(size_t k) const { return positions ? static_cast<size_t>(positions[k]) : k; }
  };
  // Coupling i's active DOFs at t; `q_local` (the local array of the state being
  // evaluated) is read only by a coupling whose activity depends on the state, and must be
  // given for one.
  ActiveDofs active(size_t i, double t, const double* q_local, Buffers& b) const;
  // The state of `dofs` from local arrays (v may be null: zero velocity), gathered into
  // b.q and b.v.
  couplings::CouplingState gather(const ActiveDofs& dofs, const double* q_local,
                                  const double* v_local, const elements::LoadPath& path, double t,
                                  Buffers& b) const;
  // Evaluates coupling i at the gathered state of its active DOFs into f (may be null)
  // and m.
  void evaluate(size_t i, const ActiveDofs& dofs, const double* q_local, const double* v_local,
                const elements::LoadPath& path, double t, double* f,
                std::span<const couplings::MatrixRequest> m, Buffers& b) const;
  // Adds coupling i's block (dofs.n², row-major) into A: whole if dense, else its nonzeros
  // (the rest of its pattern is in A already).
  void insert_block(size_t i, const ActiveDofs& dofs, const double* block, Mat A) const;
  // The force (n) or block (n², row-major) in the unknowns' rows: f_k·c_k, B_ij·c_i·c_j, into
  // out (resized); the input itself when the coefficients are all 1.
  static const double* scale_force(const ActiveDofs& dofs, const double* f,
                                   std::vector<double>& out);
  static const double* scale_block(const ActiveDofs& dofs, const double* block,
                                   std::vector<double>& out);
  void scatter_to_local(Vec global, Vec local_ghosted) const;
  // Collective. Each constraint's acceleration (or velocity) target at p into out's
  // multiplier slots (system_queries.cpp).
  void constraint_targets(const EvalPoint& p, Vec out, bool velocity) const;
  // Collective. Evaluates every coupling's force at p (or only the couplings listed in
  // `only`) and calls fn(i, dofs, f_el) (defined in visit_forces.hpp: inlined into the
  // residual loop, which runs per coupling).
  template <class Fn>
  void visit_forces(const EvalPoint& p, Fn&& fn, const std::vector<size_t>* only = nullptr) const;
  // Collective. Each combination c[r] over the couplings in `only` at p into matrices[r]
  // (zeroed first, assembled on return; null matrices are skipped), then the linear block's
  // share of it if `only` is evaluated_.
  void assemble_matrices(const EvalPoint& p, std::span<const JacobianCoefficients> c,
                         std::span<const Mat> matrices, const std::vector<size_t>& only);
  // Collective. Σ f over the couplings in `only` at p into f (global), and Σ |f_e|² over
  // those in the force scale into *squares (this rank's, if not null).
  void sum_forces(const EvalPoint& p, const std::vector<size_t>& only, Vec f,
                  double* squares) const;

  // The linearised elements as one block (linearize_elements): f = f0 + K (q − q0) + C v.
  struct LinearBlock {
    MatHandle K, C, M;
    VecHandle q0, f0, dq;  // dq: work
    double squares = 0.0;  // this rank's Σ |f0_e|²: the block's share of the force scale
  };

  MPI_Comm comm_;
  const model::Model* model_;
  Partition partition_;
  couplings::CouplingList couplings_;
  DofMap dofs_;
  // Per coupling: offset into the flat per-DOF arrays below (its dofs() resolved).
  std::vector<size_t> offset_;
  std::vector<char> acts_on_all_;  // per coupling: Coupling::acts_on_all(), cached
  std::vector<size_t> timed_;      // the couplings with PatchRole::at_patch_time
  // The couplings that enter a supported node's reaction (the constructor says which).
  std::vector<size_t> at_supports_;
  std::vector<size_t> evaluated_;    // the couplings evaluated one by one: all but linear_'s
  std::vector<size_t> constraints_;  // the constraint couplings (ConstraintCoupling)
  std::unique_ptr<LinearBlock> linear_;
  std::vector<PetscInt> local_index_;   // ghosted local index or −1 (fixed)
  std::vector<PetscInt> global_index_;  // global index or −1 (fixed)
  std::vector<double> fixed_value_;     // reference value used where fixed
  std::vector<double> coefficient_;     // per DOF: DofMap::coefficient (1 but linked slots)
  std::vector<char> has_linked_;        // per coupling: any of its slots linked
  // Not collective. Component k of a node's reference coordinates in its kind's layout: the
  // position at the kind's position slot (where a HeldPlace holds it, if one does), then the
  // ANCF gradients (tangent or the held slope, section y, section z) in threes from its
  // gradient slot; a slider's start in its fourth. The value of a fixed DOF, computed from
  // the model when asked, not stored per node on every rank.
  double reference_value(int node, int k) const;
  // Scratch of the evaluation loop (mutable: output queries evaluate through a const system).
  mutable VecHandle q_work_, v_work_, f_work_;  // ghosted work vectors
  bool has_damping_ = true;
  bool constraints_linear_ = true;
  mutable Buffers work_;
  // Local patches (prepare_local_patches): per owned DOF, the kernel couplings touching it
  // (CSR) and whether a patch may change it; marks for local_patch's search (all zero
  // between calls).
  std::vector<size_t> dof_kernel_start_, dof_kernels_;
  std::vector<char> patch_eligible_, patch_mark_;
};

}  // namespace catena::assembly
