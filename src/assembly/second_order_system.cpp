#include "catena/assembly/second_order_system.hpp"

#include <algorithm>
#include <cmath>
#include <span>
#include <type_traits>
#include <map>

#include "catena/assembly/petsc_call.hpp"
#include "catena/core/error.hpp"
#include "catena/elements/ancf_cable.hpp"
#include "catena/elements/hermite.hpp"
#include "catena/model/node_dofs.hpp"
#include "catena/core/mpi_comm.hpp"
#include "local_array.hpp"

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

SecondOrderSystem::SecondOrderSystem(MPI_Comm comm, const model::Model& model)
    : comm_(comm),
      model_(&model),
      partition_(partition_model(comm, model)),
      dofs_(model, partition_, mpi_rank(comm)) {
  const int rank = mpi_rank(comm);
  const int n_el = static_cast<int>(model.elements.size());
  for (int e = 0; e < n_el; ++e)
    if (partition_.element_owner[e] == rank) kernels_.push_back(make_element_kernel(model, e));
  for (Kernel& k : make_node_kernels(model))
    if (partition_.node_owner[k.nodes[0]] == rank) kernels_.push_back(std::move(k));

  node_reference_.resize(12 * model.nodes.size());
  for (size_t n = 0; n < model.nodes.size(); ++n) {
    const model::Node& node = model.nodes[n];
    const Vec3* blocks[4] = {&node.position, &node.tangent, &node.section_y, &node.section_z};
    for (int b = 0; b < 4; ++b)
      for (int d = 0; d < 3; ++d) node_reference_[12 * n + 3 * b + d] = (*blocks[b])[d];
  }

  kernel_offset_.push_back(0);
  for (const Kernel& k : kernels_) {
    const int dpn = k.element->dofs_per_node();
    for (int n : k.nodes)
      for (int c = 0; c < dpn; ++c) {
        local_index_.push_back(dofs_.local_dof(n, c));
        global_index_.push_back(dofs_.global_dof(n, c));
        fixed_value_.push_back(node_reference_[12 * n + c]);
      }
    kernel_offset_.push_back(local_index_.size());
    max_kernel_dofs_ = std::max(max_kernel_dofs_, static_cast<size_t>(k.element->n_dofs()));
  }

  std::vector<int> kernel_of_element(model.elements.size(), -1);
  for (size_t k = 0; k < kernels_.size(); ++k)
    if (kernels_[k].origin == KernelOrigin::element)
      kernel_of_element[kernels_[k].source] = static_cast<int>(k);
  for (const model::MovingLoad& load : model.moving_loads) {
    MovingPath path;
    path.start.push_back(0.0);
    for (int e : load.elements) {
      const auto& nodes = model.elements[e].nodes;
      const double length = (model.nodes[nodes.back()].position - model.nodes[nodes.front()].position).norm();
      path.start.push_back(path.start.back() + length);
      path.kernel.push_back(kernel_of_element[e]);
    }
    moving_paths_.push_back(std::move(path));
  }

  for (int c = 0; c < static_cast<int>(model.constraints.size()); ++c) {
    if (dofs_.constraint_owner(c) != rank) continue;
    const model::Constraint& con = model.constraints[static_cast<size_t>(c)];
    LocalConstraint lc;
    lc.index = c;
    for (int k = 0; k < 3; ++k) {
      lc.lam_local[k] = dofs_.multiplier_local(c, k);
      lc.lam_global[k] = dofs_.multiplier_dof(c, k);
      lc.a_local[k] = dofs_.local_dof(con.node_a, k);
      lc.a_global[k] = dofs_.global_dof(con.node_a, k);
      lc.b_local[k] = con.node_b >= 0 ? dofs_.local_dof(con.node_b, k) : -1;
      lc.b_global[k] = con.node_b >= 0 ? dofs_.global_dof(con.node_b, k) : -1;
    }
    constraints_.push_back(lc);
  }

  for (int c = 0; c < static_cast<int>(model.contacts.size()); ++c) {
    const model::MovingContact& contact = model.contacts[static_cast<size_t>(c)];
    if (partition_.node_owner[contact.head_node] != rank) continue;
    LocalContact lc;
    lc.index = c;
    lc.start.push_back(0.0);
    std::vector<int> path_nodes;
    for (int e : model.paths[static_cast<size_t>(contact.path)].elements) {
      const auto& nodes = model.elements[static_cast<size_t>(e)].nodes;
      lc.start.push_back(lc.start.back() + (model.nodes[static_cast<size_t>(nodes.back())].position -
                                            model.nodes[static_cast<size_t>(nodes.front())].position)
                                               .norm());
      path_nodes.insert(path_nodes.end(), nodes.begin(), nodes.end());
    }
    std::sort(path_nodes.begin(), path_nodes.end());
    path_nodes.erase(std::unique(path_nodes.begin(), path_nodes.end()), path_nodes.end());
    for (int n : path_nodes)
      for (int k = 0; k < std::min(6, dofs_.node_dofs(n)); ++k)
        if (const PetscInt g = dofs_.global_dof(n, k); g >= 0) lc.path_global.push_back(g);
    contacts_.push_back(std::move(lc));
  }

  int damps = 0;
  for (const Kernel& k : kernels_) damps |= k.element->has_damping() ? 1 : 0;
  for (const model::MovingContact& c : model.contacts) damps |= c.damping != 0.0 ? 1 : 0;
  int any = 0;
  MPI_Allreduce(&damps, &any, 1, MPI_INT, MPI_LOR, comm);
  has_damping_ = any != 0;

  q_work_ = create_vector();
  v_work_ = create_vector();
  f_work_ = create_vector();
}

void SecondOrderSystem::add_moving_loads(double t, double* f_local) const {
  for (size_t i = 0; i < moving_paths_.size(); ++i) {
    const model::MovingLoad& load = model_->moving_loads[i];
    const MovingPath& path = moving_paths_[i];
    const double s = load.start + load.speed * (t - load.start_time);
    if (t < load.start_time || s < 0.0 || s > path.start.back()) continue;  // off the path
    // The element holding s (the first one at an element boundary).
    const auto it = std::upper_bound(path.start.begin() + 1, path.start.end() - 1, s);
    const size_t e = static_cast<size_t>(it - path.start.begin()) - 1;
    const int k = path.kernel[e];
    if (k < 0) continue;  // evaluated by the rank that owns the element
    const double L = path.start[e + 1] - path.start[e];
    const elements::HermiteAt h = elements::hermite_at(std::clamp(s - path.start[e], 0.0, L), L);
    const int dpn = kernels_[static_cast<size_t>(k)].element->dofs_per_node();
    const PetscInt* idx = local_index_.data() + kernel_offset_[static_cast<size_t>(k)];
    // r(x) = S1 r_A + S2 r_A,x + S3 r_B + S4 r_B,x: the generalised force of F is Sᵀ F,
    // and f carries −f_ext.
    const int offset[4] = {0, 3, dpn, dpn + 3};
    for (int a = 0; a < 4; ++a)
      for (int d = 0; d < 3; ++d) {
        const PetscInt l = idx[offset[a] + d];
        if (l >= 0) f_local[l] -= h.s[a] * load.force[d];
      }
  }
}

VecHandle SecondOrderSystem::create_vector() const {
  VecHandle v;
  const auto& ghosts = dofs_.ghosts();
  CATENA_PETSC(VecCreateGhost(comm_, dofs_.n_owned(), dofs_.n_global(),
                              static_cast<PetscInt>(ghosts.size()), ghosts.data(), v.out()));
  CATENA_PETSC(VecSet(v.get(), 0.0));
  return v;
}

void SecondOrderSystem::preallocation(std::vector<PetscInt>& d_nnz,
                                      std::vector<PetscInt>& o_nnz) const {
  const model::Model& m = *model_;
  std::vector<std::vector<int>> node_elements(m.nodes.size());
  for (size_t e = 0; e < m.elements.size(); ++e)
    for (int n : m.elements[e].nodes) node_elements[n].push_back(static_cast<int>(e));
  const std::vector<int> counts = model::all_node_dofs(m);
  auto element_dofs = [&](int e) { return model::element_node_dofs(m.elements[e].props); };
  const PetscInt lo = dofs_.first_owned(), hi = lo + dofs_.n_owned();
  d_nnz.assign(dofs_.n_owned(), 0);
  o_nnz.assign(dofs_.n_owned(), 0);
  auto count = [&](PetscInt row, PetscInt col) {
    if (row < 0 || col < 0) return;
    (col >= lo && col < hi ? d_nnz : o_nnz)[row - lo] += 1;
  };
  // Moving contacts: the head's position rows couple with every path DOF (0..5 of each
  // path node), and those rows with the head's positions.
  for (const model::MovingContact& c : m.contacts) {
    std::vector<int> path_nodes;
    for (int e : m.paths[static_cast<size_t>(c.path)].elements)
      for (int n : m.elements[static_cast<size_t>(e)].nodes) path_nodes.push_back(n);
    std::sort(path_nodes.begin(), path_nodes.end());
    path_nodes.erase(std::unique(path_nodes.begin(), path_nodes.end()), path_nodes.end());
    for (int k = 0; k < 3; ++k) {
      const PetscInt head = dofs_.global_dof(c.head_node, k);
      if (head < 0) continue;
      for (int n : path_nodes)
        for (int j = 0; j < std::min(6, counts[static_cast<size_t>(n)]); ++j) {
          const PetscInt p = dofs_.global_dof(n, j);
          if (p < 0) continue;
          if (head >= lo && head < hi) count(head, p);
          if (p >= lo && p < hi) count(p, head);
        }
    }
  }
  // Constraints: a multiplier column in the position rows of nodes A and B, and a
  // multiplier row with A's and B's positions and the (zero) diagonal.
  for (int c = 0; c < dofs_.n_constraints(); ++c) {
    const model::Constraint& con = m.constraints[static_cast<size_t>(c)];
    for (int k = 0; k < 3; ++k) {
      const PetscInt lam = dofs_.multiplier_dof(c, k);
      for (int node : {con.node_a, con.node_b}) {
        if (node < 0) continue;
        const PetscInt row = dofs_.global_dof(node, k);
        if (row >= lo && row < hi) count(row, lam);
        if (lam >= lo && lam < hi) count(lam, row);
      }
      if (lam >= lo && lam < hi) count(lam, lam);
    }
  }
  for (int n : dofs_.owned_nodes()) {
    // (coupled node, number of its DOFs an element couples) pairs; the node's own
    // position block is always present (one-node kernels live there).
    std::vector<std::pair<int, int>> couplings{{n, 3}};
    for (int e : node_elements[n]) {
      const int d = element_dofs(e);
      for (int other : m.elements[e].nodes) couplings.emplace_back(other, d);
    }
    std::map<int, std::vector<int>> by_node;
    for (auto [other, d] : couplings) by_node[other].push_back(d);
    for (int k = 0; k < counts[n]; ++k) {
      const PetscInt row = dofs_.global_dof(n, k);
      if (row < 0) continue;
      PetscInt n_diag = 0, n_off = 0;
      for (const auto& [other, ds] : by_node) {
        int reach = 0;  // columns 0..reach-1 of `other` couple with row k
        for (int d : ds)
          if (d > k) reach = std::max(reach, d);
        for (int j = 0; j < reach; ++j) {
          const PetscInt col = dofs_.global_dof(other, j);
          if (col < 0) continue;
          (col >= lo && col < hi ? n_diag : n_off) += 1;
        }
      }
      d_nnz[row - lo] += n_diag;
      o_nnz[row - lo] += n_off;
    }
  }
}

MatHandle SecondOrderSystem::create_matrix() const {
  std::vector<PetscInt> d_nnz, o_nnz;
  preallocation(d_nnz, o_nnz);
  MatHandle J;
  CATENA_PETSC(MatCreate(comm_, J.out()));
  CATENA_PETSC(MatSetSizes(J.get(), dofs_.n_owned(), dofs_.n_owned(), dofs_.n_global(),
                           dofs_.n_global()));
  CATENA_PETSC(MatSetType(J.get(), MATAIJ));
  CATENA_PETSC(MatSeqAIJSetPreallocation(J.get(), 0, d_nnz.data()));
  CATENA_PETSC(MatMPIAIJSetPreallocation(J.get(), 0, d_nnz.data(), 0, o_nnz.data()));
  CATENA_PETSC(MatSetOption(J.get(), MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE));
  CATENA_PETSC(MatSetOption(J.get(), MAT_IGNORE_ZERO_ENTRIES, PETSC_FALSE));
  return J;
}

void SecondOrderSystem::reference_state(Vec q) const {
  PetscScalar* a = nullptr;
  CATENA_PETSC(VecGetArray(q, &a));
  for (int n : dofs_.owned_nodes())
    for (int k = 0; k < dofs_.node_dofs(n); ++k) {
      const PetscInt g = dofs_.global_dof(n, k);
      if (g >= 0) a[g - dofs_.first_owned()] = node_reference_[12 * n + k];
    }
  for (const LocalConstraint& lc : constraints_)
    for (int k = 0; k < 3; ++k) a[lc.lam_local[k]] = 0.0;
  CATENA_PETSC(VecRestoreArray(q, &a));
}

void SecondOrderSystem::scatter_to_local(Vec global, Vec local_ghosted) {
  CATENA_PETSC(VecCopy(global, local_ghosted));
  CATENA_PETSC(VecGhostUpdateBegin(local_ghosted, INSERT_VALUES, SCATTER_FORWARD));
  CATENA_PETSC(VecGhostUpdateEnd(local_ghosted, INSERT_VALUES, SCATTER_FORWARD));
}

void SecondOrderSystem::gather(size_t k, const double* q_local, const double* v_local,
                               double* q_el, double* v_el) const {
  const size_t begin = kernel_offset_[k], end = kernel_offset_[k + 1];
  for (size_t i = begin; i < end; ++i) {
    const PetscInt l = local_index_[i];
    q_el[i - begin] = l >= 0 ? q_local[l] : fixed_value_[i];
    if (v_local) v_el[i - begin] = l >= 0 ? v_local[l] : 0.0;
  }
}

template <class Fn>
void SecondOrderSystem::visit_element_forces(const EvalPoint& p, Fn&& fn) {
  scatter_to_local(p.q, q_work_.get());
  if (p.v) scatter_to_local(p.v, v_work_.get());
  const LocalArrayRead q(q_work_.get());
  std::unique_ptr<LocalArrayRead> v;
  if (p.v) v = std::make_unique<LocalArrayRead>(v_work_.get());
  std::vector<double> q_el(max_kernel_dofs_), v_el(max_kernel_dofs_), f_el(max_kernel_dofs_);
  for (size_t k = 0; k < kernels_.size(); ++k) {
    const elements::Element& el = *kernels_[k].element;
    const size_t n = static_cast<size_t>(el.n_dofs());
    gather(k, q.data(), v ? v->data() : nullptr, q_el.data(), v_el.data());
    elements::LocalState s{{q_el.data(), n}, {}, p.path};
    if (p.v) s.v = {v_el.data(), n};
    el.evaluate(s, {true, false, false}, {f_el.data(), nullptr, nullptr});
    fn(k, std::span<const double>(f_el.data(), n));
  }
}

void SecondOrderSystem::force(const EvalPoint& p, Vec f, double* element_norm) {
  const LoggedEvent logged(log_events().force);
  double squares = 0.0;
  {
    LocalArrayWrite out(f_work_.get());
    CATENA_PETSC(VecSet(out.local(), 0.0));
    double* dst = out.data();
    visit_element_forces(p, [&](size_t k, std::span<const double> f_el) {
      const PetscInt* idx = local_index_.data() + kernel_offset_[k];
      for (size_t i = 0; i < f_el.size(); ++i)
        if (idx[i] >= 0) dst[idx[i]] += f_el[i];
      if (element_norm)
        for (double x : f_el) squares += x * x;
    });
    if (!moving_paths_.empty()) add_moving_loads(p.t, dst);
    if (!constraints_.empty() || !contacts_.empty()) {
      const LocalArrayRead q(q_work_.get());  // scattered by visit_element_forces
      add_constraint_forces(p.t, q.data(), dst);
      if (!contacts_.empty()) {
        std::unique_ptr<LocalArrayRead> v;
        if (p.v) v = std::make_unique<LocalArrayRead>(v_work_.get());
        add_contact_forces(p.t, q.data(), v ? v->data() : nullptr, dst);
      }
    }
  }
  CATENA_PETSC(VecGhostUpdateBegin(f_work_.get(), ADD_VALUES, SCATTER_REVERSE));
  CATENA_PETSC(VecGhostUpdateEnd(f_work_.get(), ADD_VALUES, SCATTER_REVERSE));
  CATENA_PETSC(VecCopy(f_work_.get(), f));
  if (element_norm) {
    double global = 0.0;
    MPI_Allreduce(&squares, &global, 1, MPI_DOUBLE, MPI_SUM, comm_);
    *element_norm = std::sqrt(global);
  }
}

double SecondOrderSystem::element_force_norm(const EvalPoint& p) {
  double local = 0.0;
  visit_element_forces(p, [&](size_t, std::span<const double> f_el) {
    for (double x : f_el) local += x * x;
  });
  double global = 0.0;
  MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_SUM, comm_);
  return std::sqrt(global);
}

void SecondOrderSystem::jacobian(const EvalPoint& p, const JacobianCoefficients& c, Mat J) {
  const LoggedEvent logged(log_events().tangent);
  scatter_to_local(p.q, q_work_.get());
  if (p.v) scatter_to_local(p.v, v_work_.get());
  CATENA_PETSC(MatZeroEntries(J));
  {
    const LocalArrayRead q(q_work_.get());
    std::unique_ptr<LocalArrayRead> v;
    if (p.v) v = std::make_unique<LocalArrayRead>(v_work_.get());
    const size_t m = max_kernel_dofs_;
    std::vector<double> q_el(m), v_el(m), f_el(m), K(m * m), C(m * m), M(m * m), block(m * m);
    const elements::Request request{false, c.c_K != 0.0, c.c_C != 0.0};
    for (size_t k = 0; k < kernels_.size(); ++k) {
      const elements::Element& el = *kernels_[k].element;
      const size_t n = static_cast<size_t>(el.n_dofs());
      gather(k, q.data(), v ? v->data() : nullptr, q_el.data(), v_el.data());
      elements::LocalState s{{q_el.data(), n}, {}, p.path};
      if (p.v) s.v = {v_el.data(), n};
      el.evaluate(s, request, {f_el.data(), K.data(), C.data()});
      if (c.c_M != 0.0) el.mass(M.data());
      for (size_t i = 0; i < n * n; ++i) {
        double value = 0.0;
        if (request.stiffness) value += c.c_K * K[i];
        if (request.damping) value += c.c_C * C[i];
        if (c.c_M != 0.0) value += c.c_M * M[i];
        block[i] = value;
      }
      const PetscInt* idx = global_index_.data() + kernel_offset_[k];
      CATENA_PETSC(MatSetValues(J, static_cast<PetscInt>(n), idx, static_cast<PetscInt>(n), idx,
                                block.data(), ADD_VALUES));
    }
    add_contact_entries(p.t, q.data(), v ? v->data() : nullptr, c.c_K, c.c_C, J);
  }
  add_constraint_entries(c.c_lambda, c.c_g, J);
  CATENA_PETSC(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
  CATENA_PETSC(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
}

void SecondOrderSystem::tangent_parts(const EvalPoint& p, Mat K_out, Mat C_out) {
  const LoggedEvent logged(log_events().tangent);
  scatter_to_local(p.q, q_work_.get());
  if (p.v) scatter_to_local(p.v, v_work_.get());
  for (Mat A : {K_out, C_out})
    if (A) CATENA_PETSC(MatZeroEntries(A));
  {
    const LocalArrayRead q(q_work_.get());
    std::unique_ptr<LocalArrayRead> v;
    if (p.v) v = std::make_unique<LocalArrayRead>(v_work_.get());
    const size_t m = max_kernel_dofs_;
    std::vector<double> q_el(m), v_el(m), f_el(m), K(m * m), C(m * m);
    const elements::Request request{false, K_out != nullptr, C_out != nullptr};
    for (size_t k = 0; k < kernels_.size(); ++k) {
      const elements::Element& el = *kernels_[k].element;
      const size_t n = static_cast<size_t>(el.n_dofs());
      gather(k, q.data(), v ? v->data() : nullptr, q_el.data(), v_el.data());
      elements::LocalState s{{q_el.data(), n}, {}, p.path};
      if (p.v) s.v = {v_el.data(), n};
      el.evaluate(s, request, {f_el.data(), K.data(), C.data()});
      const PetscInt* idx = global_index_.data() + kernel_offset_[k];
      const auto N = static_cast<PetscInt>(n);
      if (K_out) CATENA_PETSC(MatSetValues(K_out, N, idx, N, idx, K.data(), ADD_VALUES));
      if (C_out) CATENA_PETSC(MatSetValues(C_out, N, idx, N, idx, C.data(), ADD_VALUES));
    }
    if (K_out) add_contact_entries(p.t, q.data(), v ? v->data() : nullptr, 1.0, 0.0, K_out);
    if (C_out) add_contact_entries(p.t, q.data(), v ? v->data() : nullptr, 0.0, 1.0, C_out);
  }
  if (K_out) add_constraint_entries(0.0, 1.0, K_out);
  if (C_out) add_constraint_entries(0.0, 0.0, C_out);
  for (Mat A : {K_out, C_out})
    if (A) {
      CATENA_PETSC(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY));
      CATENA_PETSC(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY));
    }
}

void SecondOrderSystem::section_results(const EvalPoint& p, std::vector<int>& element_indices,
                                        std::vector<elements::SectionResult>& results) {
  scatter_to_local(p.q, q_work_.get());
  const LocalArrayRead q(q_work_.get());
  element_indices.clear();
  results.clear();
  std::vector<double> q_el(max_kernel_dofs_), v_el(max_kernel_dofs_);
  for (size_t k = 0; k < kernels_.size(); ++k) {
    if (kernels_[k].origin != KernelOrigin::element) continue;
    const elements::Element& el = *kernels_[k].element;
    gather(k, q.data(), nullptr, q_el.data(), v_el.data());
    const elements::LocalState s{{q_el.data(), static_cast<size_t>(el.n_dofs())}, {},
                                 p.path};
    element_indices.push_back(kernels_[k].source);
    results.push_back(el.section_result(s));
  }
}

void SecondOrderSystem::owned_node_values(Vec q_global, std::vector<double>& positions,
                                          std::vector<double>& slopes) {
  scatter_to_local(q_global, q_work_.get());
  const LocalArrayRead q(q_work_.get());
  positions.clear();
  slopes.clear();
  for (int n : dofs_.owned_nodes()) {
    auto value = [&](int k) {
      const PetscInt l = dofs_.local_dof(n, k);
      return l >= 0 ? q.data()[l] : node_reference_[12 * n + k];
    };
    for (int d = 0; d < 3; ++d) positions.push_back(value(d));
    for (int d = 3; d < 6; ++d) slopes.push_back(dofs_.node_dofs(n) > 3 ? value(d) : 0.0);
  }
}

bool SecondOrderSystem::has_slack_prestrain() const {
  for (const auto& e : model_->elements)
    if (const auto* c = std::get_if<model::CableProps>(&e.props);
        c && !c->prestrain_with_loads && c->prestrain < elements::AncfCable::kPathPrestrain)
      return true;
  return false;
}

Reactions SecondOrderSystem::reactions(const EvalPoint& p) {
  const model::Model& m = *model_;
  // Supported nodes (any fixed DOF or an elastic support), replicated and ascending.
  std::vector<int> supported;
  for (const auto& s : m.supports) supported.push_back(s.node);
  for (const auto& s : m.elastic_supports) supported.push_back(s.node);
  std::sort(supported.begin(), supported.end());
  supported.erase(std::unique(supported.begin(), supported.end()), supported.end());
  auto slot = [&](int node) {
    return static_cast<size_t>(std::lower_bound(supported.begin(), supported.end(), node) -
                               supported.begin());
  };

  // Partial sums of the support force on each nodal DOF, completed by an allreduce.
  std::vector<double> partial(12 * supported.size(), 0.0), total(partial.size(), 0.0);
  visit_element_forces(p, [&](size_t k, std::span<const double> f_el) {
    const Kernel& kern = kernels_[k];
    const int dpn = kern.element->dofs_per_node();
    for (size_t i = 0; i < f_el.size(); ++i) {
      const int node = kern.nodes[i / dpn], comp = static_cast<int>(i % dpn);
      if (kern.origin == KernelOrigin::elastic_support)
        partial[12 * slot(node) + comp] -= f_el[i];  // the spring pulls the node back
      else if (global_index_[kernel_offset_[k] + i] < 0)
        partial[12 * slot(node) + comp] += f_el[i];  // R = f_int − f_ext at a fixed DOF
    }
  });
  MPI_Allreduce(partial.data(), total.data(), static_cast<int>(total.size()), MPI_DOUBLE,
                MPI_SUM, comm_);

  Reactions r;
  std::vector<double> positions, slopes;
  const int rank = mpi_rank(comm_);
  const LocalArrayRead q(q_work_.get());
  for (int node : supported) {
    if (partition_.node_owner[node] != rank) continue;
    const double* R = &total[12 * slot(node)];
    r.nodes.push_back(node);
    for (int d = 0; d < 3; ++d) r.force.push_back(R[d]);
    // Generalised forces Q_g on gradient g act as the moment Σ g × Q_g.
    Vec3 moment = Vec3::Zero();
    for (int b = 1; b * 3 < dofs_.node_dofs(node); ++b) {
      Vec3 grad, Q;
      for (int d = 0; d < 3; ++d) {
        const PetscInt l = dofs_.local_dof(node, 3 * b + d);
        grad[d] = l >= 0 ? q.data()[l] : node_reference_[12 * node + 3 * b + d];
        Q[d] = R[3 * b + d];
      }
      moment += grad.cross(Q);
    }
    for (int d = 0; d < 3; ++d) r.moment.push_back(moment[d]);
  }
  return r;
}

}  // namespace catena::assembly
