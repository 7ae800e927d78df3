#include "catena/assembly/second_order_system.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <span>

#include "catena/assembly/petsc_call.hpp"
#include "catena/core/error.hpp"
#include "catena/core/mpi_comm.hpp"
#include "catena/couplings/constraint_coupling.hpp"
#include "catena/couplings/element_coupling.hpp"
#include "catena/couplings/model_couplings.hpp"
#include "catena/couplings/slider_constraint.hpp"
#include "catena/model/supported_nodes.hpp"
#include "local_array.hpp"
#include "visit_forces.hpp"

namespace catena::assembly {
namespace {

using detail::LocalArrayRead;
using detail::LocalArrayWrite;

// PETSc log events, so -log_view splits a run's time into residual and tangent
// assemblies beside PETSc's own MatLUFactorNum / MatSolve (the benchmarks' breakdown).
struct LogEvents {
  PetscLogEvent force = 0, tangent = 0;
  LogEvents() {
    PetscClassId id = 0;
    PetscClassIdRegister("Catena", &id);
    PetscLogEventRegister("CatForce", id, &force);
    PetscLogEventRegister("CatTangent", id, &tangent);
  }
};
const LogEvents& log_events() {
  static const LogEvents events;  // registered after PetscInitialize, on first use
  return events;
}

// Begins a log event for the lifetime of the object.
class LoggedEvent {
 public:
  explicit LoggedEvent(PetscLogEvent e) : e_(e) { PetscLogEventBegin(e_, 0, 0, 0, 0); }
  ~LoggedEvent() { PetscLogEventEnd(e_, 0, 0, 0, 0); }
  LoggedEvent(const LoggedEvent&) = delete;
  LoggedEvent& operator=(const LoggedEvent&) = delete;

 private:
  PetscLogEvent e_;
};

}  // namespace

namespace {

// The nodes (not owned by `rank`) the couplings act on: their DOFs are this rank's ghosts.
std::vector<int> touched_nodes(const couplings::CouplingList& list) {
  std::vector<int> nodes;
  for (const auto& c : list)
    for (const couplings::DofKey& key : c->dofs())
      if (key.kind == couplings::DofKey::Kind::node) nodes.push_back(key.index);
  return nodes;
}

}  // namespace

double SecondOrderSystem::reference_value(int node, int k) const {
  const model::UnknownKindInfo& kind = model::kind_info(dofs_.node_kind(node));
  const model::Node& n = model_->nodes[static_cast<size_t>(node)];
  // Supports that hold their nodes elsewhere (model::HeldPlace): few, searched.
  const model::HeldPlace* held = nullptr;
  for (const model::HeldPlace& place : model_->held_places)
    if (place.node == node) held = &place;
  if (kind.position >= 0 && k >= kind.position && k < kind.position + 3)
    return (held ? held->position : n.position)[k - kind.position];
  if (kind.gradients >= 0 && k >= kind.gradients && k < kind.size) {
    const int b = (k - kind.gradients) / 3, d = (k - kind.gradients) % 3;
    if (b == 0) return (held ? held->slope : n.tangent)[d];
    return (b == 1 ? n.section_y : n.section_z)[d];
  }
  // A slider's arc length along its path (the fourth slot of its node, model::Slider).
  if (k == 3)
    for (const model::Slider& slider : model_->sliders)
      if (slider.node == node) return slider.start;
  return 0.0;
}

SecondOrderSystem::SecondOrderSystem(MPI_Comm comm, const model::Model& model)
    : comm_(comm),
      model_(&model),
      partition_(partition_model(comm, model)),
      couplings_(couplings::make_couplings(model, partition_.element_owner, partition_.node_owner,
                                           mpi_rank(comm))),
      dofs_(model, partition_, mpi_rank(comm), touched_nodes(couplings_)) {
  // Every coordinate held (one pinned node with a mass): nothing moves. Named here rather
  // than as the solvers' failure on an empty matrix (MUMPS INFOG(1) = -16).
  if (dofs_.n_global() == 0)
    throw InputError({model.source_file, 0, "supports"},
                     "the scene leaves no unknown free: every coordinate of every node is held "
                     "(by the scene's supports, or by a static start's holds), so nothing can "
                     "move and there is nothing to solve; free a node's coordinates or add one "
                     "that is not held");
  // Resolve every coupling's unknowns once: local and global index, value where fixed.
  std::vector<char> supported(model.nodes.size(), 0);
  for (const int node : model::supported_nodes(model)) supported[static_cast<size_t>(node)] = 1;
  offset_.push_back(0);
  for (const auto& c : couplings_) {
    bool linked = false;
    // Whether the coupling enters a support reaction (StateView::reactions): its force on a
    // supported node's fixed or linked DOF, or the force of a support-like element (an
    // elastic support, a surface, an absorbing end) on its node, or a slider's, whose
    // active DOFs move along its path. Elements at a supported node whose DOFs are all free
    // (a pipe on a surface) add nothing there and are not evaluated for it.
    bool reacts = dynamic_cast<const couplings::SliderConstraint*>(c.get()) != nullptr;
    if (const auto* e = dynamic_cast<const couplings::ElementCoupling*>(c.get()))
      reacts = reacts || couplings::acts_as_support(e->origin());
    for (const couplings::DofKey& key : c->dofs()) {
      PetscInt local = -1, global = -1;
      double fixed = 0.0, coefficient = 1.0;
      if (key.kind == couplings::DofKey::Kind::multiplier) {
        local = dofs_.multiplier_local(key.index, key.component);
        global = dofs_.multiplier_dof(key.index, key.component);
      } else {
        CATENA_ASSERT(key.component < dofs_.node_dofs(key.index),
                      "a coupling asks for a component its node's kind has");
        fixed = reference_value(key.index, key.component);
        local = dofs_.local_dof(key.index, key.component);
        global = dofs_.global_dof(key.index, key.component);
        coefficient = dofs_.coefficient(key.index, key.component);
        const bool linked_dof = dofs_.linked(key.index, key.component);
        linked = linked || linked_dof;
        reacts = reacts || (supported[key.index] && (global < 0 || linked_dof));
      }
      CATENA_ASSERT(global < 0 || local >= 0, "a coupling's free DOF is on this rank");
      local_index_.push_back(local);
      global_index_.push_back(global);
      fixed_value_.push_back(fixed);
      coefficient_.push_back(coefficient);
    }
    has_linked_.push_back(linked ? 1 : 0);
    offset_.push_back(local_index_.size());
    acts_on_all_.push_back(c->acts_on_all() ? 1 : 0);
    if (c->patch_role() == couplings::PatchRole::at_patch_time)
      timed_.push_back(acts_on_all_.size() - 1);
    if (reacts &&
        std::any_of(c->dofs().begin(), c->dofs().end(), [&](const couplings::DofKey& key) {
          return key.kind != couplings::DofKey::Kind::multiplier && supported[key.index];
        }))
      at_supports_.push_back(acts_on_all_.size() - 1);
  }

  evaluated_.resize(couplings_.size());
  for (size_t i = 0; i < couplings_.size(); ++i) evaluated_[i] = i;

  bool damps = false;
  for (const auto& c : couplings_) damps = damps || c->has_damping();
  has_damping_ = any_rank(comm, damps);
  bool nonlinear = false;
  for (size_t i = 0; i < couplings_.size(); ++i)
    if (const auto* k = dynamic_cast<const couplings::ConstraintCoupling*>(couplings_[i].get())) {
      constraints_.push_back(i);
      nonlinear = nonlinear || !k->linear();
    }
  constraints_linear_ = !any_rank(comm, nonlinear);

  q_work_ = create_vector();
  v_work_ = create_vector();
  f_work_ = create_vector();
}

namespace {

// A coupling's DOF values in a local array, as gather() reads them.
class LocalDofValues final : public couplings::DofValues {
 public:
  LocalDofValues(const double* q_local, const PetscInt* local, const double* fixed,
                 const double* coefficient)
      : q_(q_local), local_(local), fixed_(fixed), coefficient_(coefficient) {}
  double at(int position) const override {
    const PetscInt l = local_[position];
    if (l < 0) return fixed_[position];
    return coefficient_[position] * q_[l];
  }

 private:
  const double* q_;
  const PetscInt* local_;
  const double* fixed_;
  const double* coefficient_;
};

}  // namespace

SecondOrderSystem::ActiveDofs SecondOrderSystem::active(size_t i, double t, const double* q_local,
                                                        Buffers& b) const {
  const size_t begin = offset_[i];
  const bool linked = has_linked_[i] != 0;
  if (acts_on_all_[i])
    return {local_index_.data() + begin, global_index_.data() + begin, fixed_value_.data() + begin,
            linked ? coefficient_.data() + begin : nullptr, offset_[i + 1] - begin};
  if (couplings_[i]->state_dependent_activity()) {
    CATENA_ASSERT(q_local != nullptr, "a coupling whose activity follows the state needs it");
    const LocalDofValues values(q_local, local_index_.data() + begin, fixed_value_.data() + begin,
                                coefficient_.data() + begin);
    couplings_[i]->active_dofs_at(t, values, b.positions);
  } else {
    couplings_[i]->active_dofs(t, b.positions);
  }
  b.local.clear();
  b.global.clear();
  b.fixed.clear();
  b.coefficient.clear();
  for (int pos : b.positions) {
    const size_t k = begin + static_cast<size_t>(pos);
    b.local.push_back(local_index_[k]);
    b.global.push_back(global_index_[k]);
    b.fixed.push_back(fixed_value_[k]);
    b.coefficient.push_back(coefficient_[k]);
  }
  return {b.local.data(),     b.global.data(),
          b.fixed.data(),     linked ? b.coefficient.data() : nullptr,
          b.positions.size(), b.positions.data()};
}

const double* SecondOrderSystem::scale_force(const ActiveDofs& dofs, const double* f,
                                             std::vector<double>& out) {
  if (!dofs.coefficient) return f;
  out.resize(dofs.n);
  for (size_t k = 0; k < dofs.n; ++k) out[k] = dofs.coefficient[k] * f[k];
  return out.data();
}

const double* SecondOrderSystem::scale_block(const ActiveDofs& dofs, const double* block,
                                             std::vector<double>& out) {
  if (!dofs.coefficient) return block;
  const size_t n = dofs.n;
  out.resize(n * n);
  for (size_t r = 0; r < n; ++r)
    for (size_t c = 0; c < n; ++c)
      out[r * n + c] = dofs.coefficient[r] * dofs.coefficient[c] * block[r * n + c];
  return out.data();
}

couplings::CouplingState SecondOrderSystem::gather(const ActiveDofs& dofs, const double* q_local,
                                                   const double* v_local,
                                                   const elements::LoadPath& path, double t,
                                                   Buffers& b) const {
  const size_t n = dofs.n;
  if (b.q.size() < n) {
    b.q.resize(n);
    b.v.resize(n);
  }
  for (size_t k = 0; k < n; ++k) {
    const PetscInt l = dofs.local[k];
    b.q[k] = l >= 0 ? q_local[l] : dofs.fixed[k];
    if (v_local) b.v[k] = l >= 0 ? v_local[l] : 0.0;
  }
  if (dofs.coefficient)  // a clamp's linked slope: nodal value = coefficient × unknown
    for (size_t k = 0; k < n; ++k)
      if (dofs.local[k] >= 0) {
        b.q[k] *= dofs.coefficient[k];
        if (v_local) b.v[k] *= dofs.coefficient[k];
      }
  couplings::CouplingState s{{b.q.data(), n}, {}, path, t};
  if (v_local) s.v = {b.v.data(), n};
  return s;
}

void SecondOrderSystem::evaluate(size_t i, const ActiveDofs& dofs, const double* q_local,
                                 const double* v_local, const elements::LoadPath& path, double t,
                                 double* f, std::span<const couplings::MatrixRequest> m,
                                 Buffers& b) const {
  couplings_[i]->evaluate(gather(dofs, q_local, v_local, path, t, b), f, m, b.scratch);
}

void SecondOrderSystem::insert_block(size_t i, const ActiveDofs& dofs, const double* nodal_block,
                                     Mat A) const {
  const auto n = static_cast<PetscInt>(dofs.n);
  // Linked slots share a global index: PETSc adds the repeated entries (ADD_VALUES).
  const double* block = scale_block(dofs, nodal_block, work_.scaled);
  if (couplings_[i]->dense()) {
    CATENA_PETSC(MatSetValues(A, n, dofs.global, n, dofs.global, block, ADD_VALUES));
    return;
  }
  for (PetscInt r = 0; r < n; ++r)
    for (PetscInt c = 0; c < n; ++c)
      if (const double value = block[r * n + c]; value != 0.0)
        CATENA_PETSC(MatSetValue(A, dofs.global[r], dofs.global[c], value, ADD_VALUES));
}

VecHandle SecondOrderSystem::create_vector() const {
  VecHandle v;
  const auto& ghosts = dofs_.ghosts();
  CATENA_PETSC(VecCreateGhost(comm_, dofs_.n_owned(), dofs_.n_global(),
                              static_cast<PetscInt>(ghosts.size()), ghosts.data(), v.out()));
  CATENA_PETSC(VecSet(v.get(), 0.0));
  return v;
}

void SecondOrderSystem::reference_state(Vec q) const {
  PetscScalar* a = nullptr;
  CATENA_PETSC(VecGetArray(q, &a));
  for (int n : dofs_.owned_nodes()) {
    for (int k = 0; k < dofs_.node_dofs(n); ++k)
      if (const PetscInt g = dofs_.global_dof(n, k); g >= 0) a[g - dofs_.first_owned()] = 0.0;
    // Σ c_k·value_k: the value itself, or on a linked slope its projection on the tangent
    // (the unknown s = 1 at the reference).
    for (int k = 0; k < dofs_.node_dofs(n); ++k)
      if (const PetscInt g = dofs_.global_dof(n, k); g >= 0)
        a[g - dofs_.first_owned()] += dofs_.coefficient(n, k) * reference_value(n, k);
  }
  for (int c = 0; c < dofs_.n_constraints(); ++c)
    for (int k = 0; k < dofs_.n_multipliers(c); ++k)
      if (const PetscInt l = dofs_.multiplier_local(c, k); l >= 0) a[l] = 0.0;
  CATENA_PETSC(VecRestoreArray(q, &a));
}

void SecondOrderSystem::scatter_to_local(Vec global, Vec local_ghosted) const {
  CATENA_PETSC(VecCopy(global, local_ghosted));
  CATENA_PETSC(VecGhostUpdateBegin(local_ghosted, INSERT_VALUES, SCATTER_FORWARD));
  CATENA_PETSC(VecGhostUpdateEnd(local_ghosted, INSERT_VALUES, SCATTER_FORWARD));
}

void SecondOrderSystem::sum_forces(const EvalPoint& p, const std::vector<size_t>& only, Vec f,
                                   double* squares) const {
  {
    LocalArrayWrite out(f_work_.get());
    CATENA_PETSC(VecSet(out.local(), 0.0));
    double* dst = out.data();
    visit_forces(
        p,
        [&](size_t i, const ActiveDofs& dofs, std::span<const double> f_el) {
          const double* f_rows = scale_force(dofs, f_el.data(), work_.scaled);
          for (size_t k = 0; k < f_el.size(); ++k)
            if (dofs.local[k] >= 0) dst[dofs.local[k]] += f_rows[k];
          if (squares && couplings_[i]->in_force_scale())
            for (double x : f_el) *squares += x * x;
        },
        &only);
  }
  CATENA_PETSC(VecGhostUpdateBegin(f_work_.get(), ADD_VALUES, SCATTER_REVERSE));
  CATENA_PETSC(VecGhostUpdateEnd(f_work_.get(), ADD_VALUES, SCATTER_REVERSE));
  CATENA_PETSC(VecCopy(f_work_.get(), f));
}

void SecondOrderSystem::constraint_residual(const EvalPoint& p, Vec out) const {
  sum_forces(p, constraints_, out, nullptr);
}

void SecondOrderSystem::force(const EvalPoint& p, Vec f, double* element_norm) {
  const LoggedEvent logged(log_events().force);
  double squares = 0.0;
  sum_forces(p, evaluated_, f, element_norm ? &squares : nullptr);
  if (linear_) {
    // f += f0 + K (q − q0) + C v: the difference first, so that no product of the stiffness
    // with absolute coordinates (10⁷ N/m × 600 m) cancels against f0 in round-off.
    CATENA_PETSC(VecWAXPY(linear_->dq.get(), -1.0, linear_->q0.get(), p.q));
    CATENA_PETSC(MatMultAdd(linear_->K.get(), linear_->dq.get(), f, f));
    if (p.v) CATENA_PETSC(MatMultAdd(linear_->C.get(), p.v, f, f));
    CATENA_PETSC(VecAXPY(f, 1.0, linear_->f0.get()));
    squares += linear_->squares;
  }
  if (element_norm) {
    double global = 0.0;
    MPI_Allreduce(&squares, &global, 1, MPI_DOUBLE, MPI_SUM, comm_);
    *element_norm = std::sqrt(global);
  }
}

double SecondOrderSystem::element_force_norm(const EvalPoint& p) {
  double local = linear_ ? linear_->squares : 0.0;
  visit_forces(
      p,
      [&](size_t i, const ActiveDofs&, std::span<const double> f_el) {
        if (couplings_[i]->in_force_scale())
          for (double x : f_el) local += x * x;
      },
      &evaluated_);
  double global = 0.0;
  MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_SUM, comm_);
  return std::sqrt(global);
}

void SecondOrderSystem::assemble_matrices(const EvalPoint& p,
                                          std::span<const JacobianCoefficients> c,
                                          std::span<const Mat> matrices,
                                          const std::vector<size_t>& only) {
  const LoggedEvent logged(log_events().tangent);
  scatter_to_local(p.q, q_work_.get());
  if (p.v) scatter_to_local(p.v, v_work_.get());
  CATENA_ASSERT(matrices.size() <= 2, "assemble_matrices: at most two matrices per pass");
  std::vector<couplings::MatrixRequest> requests;
  std::vector<Mat> targets;
  std::vector<JacobianCoefficients> coefficients;
  for (size_t r = 0; r < matrices.size(); ++r)
    if (matrices[r]) {
      CATENA_PETSC(MatZeroEntries(matrices[r]));
      requests.push_back({c[r], nullptr});
      targets.push_back(matrices[r]);
      coefficients.push_back(c[r]);
    }
  {
    const LocalArrayRead q(q_work_.get());
    std::unique_ptr<LocalArrayRead> v;
    if (p.v) v = std::make_unique<LocalArrayRead>(v_work_.get());
    std::vector<double>* blocks[2] = {&work_.block, &work_.block2};
    for (const size_t i : only) {
      const ActiveDofs dofs = active(i, p.t, q.data(), work_);
      if (dofs.n == 0) continue;
      for (size_t r = 0; r < requests.size(); ++r) {
        if (blocks[r]->size() < dofs.n * dofs.n) blocks[r]->resize(dofs.n * dofs.n);
        requests[r].out = blocks[r]->data();
      }
      evaluate(i, dofs, q.data(), v ? v->data() : nullptr, p.path, p.t, nullptr, requests, work_);
      for (size_t r = 0; r < requests.size(); ++r)
        insert_block(i, dofs, requests[r].out, targets[r]);
    }
  }
  for (Mat A : targets) {
    CATENA_PETSC(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY));
    CATENA_PETSC(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY));
  }
  if (!linear_ || &only != &evaluated_) return;
  // Every matrix has the system's whole pattern (create_matrix): a sum of arrays.
  for (size_t r = 0; r < targets.size(); ++r) {
    const JacobianCoefficients& k = coefficients[r];
    if (k.c_K != 0.0)
      CATENA_PETSC(MatAXPY(targets[r], k.c_K, linear_->K.get(), SAME_NONZERO_PATTERN));
    if (k.c_C != 0.0)
      CATENA_PETSC(MatAXPY(targets[r], k.c_C, linear_->C.get(), SAME_NONZERO_PATTERN));
    if (k.c_M != 0.0)
      CATENA_PETSC(MatAXPY(targets[r], k.c_M, linear_->M.get(), SAME_NONZERO_PATTERN));
  }
}

void SecondOrderSystem::jacobian(const EvalPoint& p, const JacobianCoefficients& c, Mat J) {
  const Mat matrices[1] = {J};
  assemble_matrices(p, {&c, 1}, matrices, evaluated_);
}

void SecondOrderSystem::constraint_jacobian(const EvalPoint& p, const JacobianCoefficients& c,
                                            Mat J) {
  const Mat matrices[1] = {J};
  assemble_matrices(p, {&c, 1}, matrices, constraints_);
}

void SecondOrderSystem::tangent_parts(const EvalPoint& p, Mat K_out, Mat C_out) {
  // K carries G in the multiplier rows (∂R/∂q of the whole residual); C is ∂f/∂v.
  const JacobianCoefficients c[2] = {{1.0, 0.0, 0.0, 0.0, 1.0}, {0.0, 1.0, 0.0, 0.0, 0.0}};
  const Mat matrices[2] = {K_out, C_out};
  assemble_matrices(p, c, matrices, evaluated_);
}

}  // namespace catena::assembly
