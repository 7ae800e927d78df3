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
// The constraints are linear in q (positions only), so G is constant.
#include <mpi.h>
#include <petscmat.h>

#include <memory>
#include <string>
#include <vector>

#include "catena/assembly/dof_map.hpp"
#include "catena/assembly/element_factory.hpp"
#include "catena/assembly/local_patch.hpp"
#include "catena/assembly/partition.hpp"
#include "catena/assembly/petsc_handle.hpp"
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

struct JacobianCoefficients {
  double c_K = 1.0;       // ∂f/∂q
  double c_C = 0.0;       // ∂f/∂v
  double c_M = 0.0;       // M
  double c_lambda = 0.0;  // Gᵀ (nodal rows, multiplier columns)
  double c_g = 0.0;       // G (multiplier rows, nodal columns)
};
// Statics: J = ∂f/∂q + Gᵀ + G (symmetric).
inline constexpr JacobianCoefficients kStaticJacobian{1.0, 0.0, 0.0, 1.0, 1.0};

// Per supported node (owned by this rank): reaction of the supports on the node.
struct Reactions {
  std::vector<int> nodes;       // ascending model node indices
  std::vector<double> force;    // 3 per node, N
  std::vector<double> moment;   // 3 per node, N·m (from fixed slope DOFs)
};

class SecondOrderSystem {
 public:
  // Collective: partitions the model, numbers DOFs, builds this rank's kernels.
  SecondOrderSystem(MPI_Comm comm, const model::Model& model);
  SecondOrderSystem(const SecondOrderSystem&) = delete;  // dofs_ points into partition_
  SecondOrderSystem& operator=(const SecondOrderSystem&) = delete;

  MPI_Comm comm() const { return comm_; }
  const model::Model& model() const { return *model_; }
  const DofMap& dof_map() const { return dofs_; }

  // Collective. A ghosted vector laid out as the free DOFs.
  VecHandle create_vector() const;
  // Collective. An MPIAIJ matrix with exact preallocation; inserting outside the pattern
  // is an error (MAT_NEW_NONZERO_ALLOCATION_ERR), so assembly never mallocs.
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
  // Collective. K = ∂f/∂q + G (G in the multiplier rows: ∂R/∂q of the whole residual)
  // and C = ∂f/∂v at p in one element pass (matrices from create_matrix(); either may be
  // null). For integrators that combine them with coefficients of their own; the
  // multiplier columns Gᵀ come from jacobian() with c_λ = 1 (constant).
  void tangent_parts(const EvalPoint& p, Mat K, Mat C);

  // Local patches (local_patch.hpp; local_patch.cpp). Collective: finds which owned DOFs
  // a patch may change alone. Once, before the first local_patch().
  void prepare_local_patches();
  // Not collective. The patch around `seeds` (owned local indices) at time t: the DOFs
  // reached from them across `layers` kernels (a moving contact counts as one), those of
  // them a patch may change alone.
  LocalPatch local_patch(const std::vector<PetscInt>& seeds, int layers, double t = 0.0);
  // Not collective. Σ f_e(q, v) over the patch's kernels and contacts, per row (f_rows: rows.size()),
  // from the owned arrays of q and v (v may be null: zero velocity). Moving loads are left
  // out: they do not depend on the state, so they cancel in a change of the residual.
  void patch_force(const LocalPatch& patch, const double* q, const double* v,
                   double* f_rows) const;
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

  // Moving contacts (model::MovingContact, pantograph heads on a wire).
  struct ContactState {
    double force = 0.0;        // N, ≥ 0 (0: no contact)
    double position = 0.0;     // m along the path (the pantograph's position)
    double penetration = 0.0;  // m, (r_head − r_wire)·up; > 0 in contact
    bool on_path = false;      // the contact point is on its path
  };
  // Collective. Every contact's state at p (identical on every rank).
  std::vector<ContactState> contact_states(const EvalPoint& p);

  // Constraints (Lagrange multipliers).
  bool has_constraints() const { return !model_->constraints.empty(); }
  // Collective. 1 in the multiplier slots, 0 in the nodal ones.
  void algebraic_mask(Vec mask) const;
  // Collective. ∂²u/∂t² of the prescribed motions at t in the multiplier slots (0 in the
  // others): with G constant, the acceleration-level constraint is G a = that.
  void constraint_acceleration(double t, Vec out) const;

  // Collective. Section results for this rank's model elements (ascending index).
  void section_results(const EvalPoint& p, std::vector<int>& elements,
                       std::vector<elements::SectionResult>& results);
  // Collective. Full nodal values (fixed DOFs included) of owned nodes: positions and
  // slopes (∂r/∂x, zero where a node has none), 3 each.
  void owned_node_values(Vec q, std::vector<double>& positions, std::vector<double>& slopes);
  // Not collective. x's free DOFs of the owned nodes in the full nodal layout, 12 values
  // per node of dof_map().owned_nodes() (fixed and absent components 0), and this rank's
  // multiplier slots (3 per owned constraint, ascending): a partition-independent form.
  void owned_node_rows(Vec x, std::vector<double>& rows, std::vector<double>& multipliers) const;
  // Not collective. The inverse for every node and constraint at once: x's owned free DOFs
  // from rows (12 per node, all nodes) and its owned multiplier slots from multipliers (3
  // per constraint, all constraints).
  void set_from_node_rows(Vec x, const std::vector<double>& rows,
                          const std::vector<double>& multipliers) const;
  // Not collective. This rank's constraints (ascending index) and the force each applies
  // to its node A, −λ (3 per constraint, N), from the multiplier slots of q.
  void owned_constraint_forces(Vec q, std::vector<int>& constraints,
                               std::vector<double>& forces) const;
  // Collective. Support reactions at owned supported nodes.
  Reactions reactions(const EvalPoint& p);

  // True if the static load path needs its second phase (some cable's prestrain is below
  // the path's tensioning prestrain, see elements::LocalState).
  bool has_slack_prestrain() const;

  // A global DOF in words, for messages: "node 17 (y)" or "constraint 2 (multiplier y,
  // node 5)" (node ids as in the scene; constraints numbered from 1 in scene order).
  std::string describe_dof(PetscInt global) const;

  // Number of kernels this rank evaluates (for load-balance reports).
  size_t n_local_kernels() const { return kernels_.size(); }

 private:
  void scatter_to_local(Vec global, Vec local_ghosted);
  // Collective. Evaluates every local kernel's force at p and calls fn(kernel, f_el).
  template <class Fn>
  void visit_element_forces(const EvalPoint& p, Fn&& fn);
  // Gathers kernel k's local state from the ghosted local arrays.
  void gather(size_t k, const double* q_local, const double* v_local, double* q_el,
              double* v_el) const;
  // Evaluates kernel k at owned arrays q, v (v may be null; every DOF of k owned, as in a
  // local patch) into out, with caller buffers for its local state; returns its DOF count.
  size_t evaluate_owned(size_t k, const double* q, const double* v, elements::Request request,
                        elements::LocalOutput out, double* q_el, double* v_el) const;
  void preallocation(std::vector<PetscInt>& d_nnz, std::vector<PetscInt>& o_nnz) const;
  // Adds −f_ext of the moving loads at time t into the ghosted local force array.
  void add_moving_loads(double t, double* f_local) const;
  // Adds Gᵀλ and g(q, t) of this rank's constraints into the ghosted local force array.
  void add_constraint_forces(double t, const double* q_local, double* f_local) const;
  // Inserts c_λ Gᵀ + c_g G of this rank's constraints (and a zero multiplier diagonal).
  void add_constraint_entries(double c_lambda, double c_g, Mat J) const;

  // Moving contacts evaluated by this rank (the owner of the head node): the path's
  // cumulative reference lengths and the DOFs involved.
  struct LocalContact {
    int index = 0;                // into Model::contacts
    std::vector<double> start;    // per path element, + total length at the end
    std::vector<PetscInt> path_global;  // free DOFs of the path's nodes (pattern)
  };
  std::vector<LocalContact> contacts_;
  // The contact's penetration δ = N·q (and δ̇ = N·v + D·q) over its 15 involved DOFs at
  // time t: head position (3), then the wire element's r_A, r_A,x, r_B, r_B,x; local and
  // global indices (−1 fixed) and the fixed values; false when off the path.
  struct ContactGeometry {
    PetscInt local[15], global[15];
    double fixed[15];
    double N[15], D[15];
    double position = 0.0;
  };
  bool contact_geometry(const LocalContact& c, double t, ContactGeometry& g) const;
  // Penalty force from the geometry and the local state arrays (0 if separated).
  double contact_force(const model::MovingContact& c, const ContactGeometry& g, const double* q,
                       const double* v, double* penetration = nullptr) const;
  // Adds this rank's contact forces into the ghosted local force array.
  void add_contact_forces(double t, const double* q_local, const double* v_local,
                          double* f_local) const;
  // Inserts c_K K + c_C C of the contacts (and zeros over the whole preallocated coupling).
  void add_contact_entries(double t, const double* q_local, const double* v_local, double c_K,
                           double c_C, Mat J) const;

  // A constraint owned by this rank: indices of its multipliers and of the position DOFs
  // of its nodes (B: −1 when absent), ghosted local and global.
  struct LocalConstraint {
    int index = 0;
    PetscInt lam_local[3], lam_global[3];
    PetscInt a_local[3], a_global[3];
    PetscInt b_local[3], b_global[3];
  };
  std::vector<LocalConstraint> constraints_;

  // Per moving load: cumulative reference length at the start of each path element, and
  // the local kernel index of each path element (−1: another rank's).
  struct MovingPath {
    std::vector<double> start;   // size n_elements + 1 (last: total length)
    std::vector<int> kernel;
  };
  std::vector<MovingPath> moving_paths_;

  MPI_Comm comm_;
  const model::Model* model_;
  Partition partition_;
  DofMap dofs_;
  std::vector<Kernel> kernels_;
  // Per kernel: offset into the flat per-local-DOF arrays below.
  std::vector<size_t> kernel_offset_;
  std::vector<PetscInt> local_index_;   // ghosted local index or −1 (fixed)
  std::vector<PetscInt> global_index_;  // global index or −1 (fixed)
  std::vector<double> fixed_value_;     // reference value used where fixed
  std::vector<double> node_reference_;  // 12 per node: [X, t, d_y, d_z]
  VecHandle q_work_, v_work_, f_work_;  // ghosted work vectors
  size_t max_kernel_dofs_ = 0;
  bool has_damping_ = true;
  // Local patches (prepare_local_patches): per owned DOF, the kernels touching it (CSR) and
  // whether a patch may change it; marks for local_patch's search (kept all zero between calls).
  std::vector<size_t> dof_kernel_start_, dof_kernels_;
  std::vector<char> patch_eligible_, patch_mark_;
};

}  // namespace catena::assembly
