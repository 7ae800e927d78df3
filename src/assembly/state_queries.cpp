// SecondOrderSystem, part: what output and messages ask of a state — section results, node
// values, reactions, contact states, multipliers, node-indexed rows and DOF names (the
// class: include/catena/assembly/second_order_system.hpp).
#include <algorithm>
#include <memory>
#include <string>

#include "catena/assembly/petsc_call.hpp"
#include "catena/assembly/second_order_system.hpp"
#include "catena/core/error.hpp"
#include "catena/core/mpi_comm.hpp"
#include "catena/couplings/element_coupling.hpp"
#include "catena/couplings/node_constraint.hpp"
#include "catena/couplings/pantograph_contact.hpp"
#include "catena/elements/ancf_cable.hpp"
#include "local_array.hpp"
#include "visit_forces.hpp"

namespace catena::assembly {

using detail::LocalArrayRead;
using couplings::ElementCoupling;
using couplings::ElementOrigin;

void SecondOrderSystem::section_results(const EvalPoint& p, std::vector<int>& element_indices,
                                        std::vector<elements::SectionResult>& results) {
  scatter_to_local(p.q, q_work_.get());
  const LocalArrayRead q(q_work_.get());
  element_indices.clear();
  results.clear();
  for (size_t i = 0; i < couplings_.size(); ++i) {
    const auto* e = dynamic_cast<const ElementCoupling*>(couplings_[i].get());
    if (!e || e->origin() != ElementOrigin::element) continue;
    const couplings::CouplingState g =
        gather(active(i, p.t, work_), q.data(), nullptr, p.path, p.t, work_);
    const elements::LocalState s{g.q, {}, p.path};
    element_indices.push_back(e->source());
    results.push_back(e->element().section_result(s));
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

  // Partial sums of the support force on each nodal DOF, completed by an allreduce. The
  // element couplings carry it: R = f_int − f_ext at a fixed DOF, and an elastic support
  // pulls its node back.
  std::vector<double> partial(12 * supported.size(), 0.0), total(partial.size(), 0.0);
  visit_forces(p, [&](size_t i, const ActiveDofs& dofs, std::span<const double> f_el) {
    const auto* e = dynamic_cast<const ElementCoupling*>(couplings_[i].get());
    if (!e) return;
    const std::vector<couplings::DofKey>& keys = e->dofs();
    for (size_t k = 0; k < f_el.size(); ++k) {
      const int node = keys[k].index, comp = keys[k].component;
      if (e->origin() == ElementOrigin::elastic_support)
        partial[12 * slot(node) + comp] -= f_el[k];
      else if (dofs.global[k] < 0)
        partial[12 * slot(node) + comp] += f_el[k];
    }
  });
  MPI_Allreduce(partial.data(), total.data(), static_cast<int>(total.size()), MPI_DOUBLE,
                MPI_SUM, comm_);

  Reactions r;
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

std::vector<SecondOrderSystem::ContactState> SecondOrderSystem::contact_states(
    const EvalPoint& p) {
  const size_t n = model_->contacts.size();
  if (n == 0) return {};
  std::vector<double> local(4 * n, 0.0), global(4 * n, 0.0);
  scatter_to_local(p.q, q_work_.get());
  if (p.v) scatter_to_local(p.v, v_work_.get());
  {
    const LocalArrayRead q(q_work_.get());
    std::unique_ptr<LocalArrayRead> v;
    if (p.v) v = std::make_unique<LocalArrayRead>(v_work_.get());
    for (size_t i = 0; i < couplings_.size(); ++i) {
      const auto* c = dynamic_cast<const couplings::PantographContact*>(couplings_[i].get());
      if (!c) continue;
      const size_t k = static_cast<size_t>(c->index());
      const bool on = c->on_path(p.t);
      double delta = 0.0, F = 0.0;
      if (on) {
        F = c->force(gather(active(i, p.t, work_), q.data(), v ? v->data() : nullptr, p.path,
                            p.t, work_),
                     &delta);
      }
      local[4 * k] = F;
      local[4 * k + 1] = c->position(p.t);
      local[4 * k + 2] = delta;
      local[4 * k + 3] = on ? 1.0 : 0.0;
    }
  }
  MPI_Allreduce(local.data(), global.data(), static_cast<int>(global.size()), MPI_DOUBLE, MPI_SUM,
                comm_);
  std::vector<ContactState> out(n);
  for (size_t i = 0; i < n; ++i)
    out[i] = {global[4 * i], global[4 * i + 1], global[4 * i + 2], global[4 * i + 3] > 0.5};
  return out;
}

std::string SecondOrderSystem::describe_dof(PetscInt global) const {
  static const char* names[12] = {"x",    "y",    "z",    "rx_x", "rx_y", "rx_z",
                                  "ry_x", "ry_y", "ry_z", "rz_x", "rz_y", "rz_z"};
  if (global < 0 || global >= dofs_.n_global()) return "unknown DOF";
  const int node = dofs_.node_of_global(global);
  const int comp = dofs_.component_of_global(global);
  const std::string id = std::to_string(model_->nodes[static_cast<size_t>(node)].id);
  if (const int c = dofs_.constraint_of_global(global); c >= 0)
    return "constraint " + std::to_string(c + 1) + " (multiplier " + names[comp] + ", node " +
           id + ")";
  return "node " + id + " (" + (comp >= 0 ? names[comp] : "?") + ")";
}

void SecondOrderSystem::owned_node_rows(Vec x, std::vector<double>& rows,
                                        std::vector<double>& multipliers) const {
  rows.clear();
  multipliers.clear();
  const PetscScalar* a = nullptr;
  CATENA_PETSC(VecGetArrayRead(x, &a));
  for (int n : dofs_.owned_nodes())
    for (int k = 0; k < 12; ++k) {
      const PetscInt g = k < dofs_.node_dofs(n) ? dofs_.global_dof(n, k) : -1;
      rows.push_back(g >= 0 ? a[g - dofs_.first_owned()] : 0.0);
    }
  for (int c = 0; c < dofs_.n_constraints(); ++c)
    for (int k = 0; k < 3; ++k)
      if (const PetscInt l = dofs_.multiplier_local(c, k); l >= 0) multipliers.push_back(a[l]);
  CATENA_PETSC(VecRestoreArrayRead(x, &a));
}

void SecondOrderSystem::set_from_node_rows(Vec x, const std::vector<double>& rows,
                                           const std::vector<double>& multipliers) const {
  CATENA_ASSERT(rows.size() == 12 * model_->nodes.size() &&
                    multipliers.size() == 3 * model_->constraints.size(),
                "12 values per node, 3 per constraint");
  PetscScalar* a = nullptr;
  CATENA_PETSC(VecGetArray(x, &a));
  for (int n : dofs_.owned_nodes())
    for (int k = 0; k < dofs_.node_dofs(n); ++k) {
      const PetscInt g = dofs_.global_dof(n, k);
      if (g >= 0) a[g - dofs_.first_owned()] = rows[12 * static_cast<size_t>(n) + k];
    }
  for (int c = 0; c < dofs_.n_constraints(); ++c)
    for (int k = 0; k < 3; ++k)
      if (const PetscInt l = dofs_.multiplier_local(c, k); l >= 0)
        a[l] = multipliers[3 * static_cast<size_t>(c) + k];
  CATENA_PETSC(VecRestoreArray(x, &a));
}

void SecondOrderSystem::owned_constraint_forces(Vec q, std::vector<int>& constraints,
                                                std::vector<double>& forces) const {
  constraints.clear();
  forces.clear();
  const PetscScalar* a = nullptr;
  CATENA_PETSC(VecGetArrayRead(q, &a));
  for (int c = 0; c < dofs_.n_constraints(); ++c) {
    if (dofs_.multiplier_local(c, 0) < 0) continue;
    constraints.push_back(c);
    for (int k = 0; k < 3; ++k) forces.push_back(-a[dofs_.multiplier_local(c, k)]);
  }
  CATENA_PETSC(VecRestoreArrayRead(q, &a));
}

void SecondOrderSystem::algebraic_mask(Vec mask) const {
  CATENA_PETSC(VecSet(mask, 0.0));
  for (int c = 0; c < dofs_.n_constraints(); ++c)
    if (dofs_.multiplier_local(c, 0) >= 0)
      for (int k = 0; k < 3; ++k)
        CATENA_PETSC(VecSetValue(mask, dofs_.multiplier_dof(c, k), 1.0, INSERT_VALUES));
  CATENA_PETSC(VecAssemblyBegin(mask));
  CATENA_PETSC(VecAssemblyEnd(mask));
}

void SecondOrderSystem::constraint_acceleration(double t, Vec out) const {
  CATENA_PETSC(VecSet(out, 0.0));
  for (const auto& coupling : couplings_) {
    const auto* c = dynamic_cast<const couplings::NodeConstraint*>(coupling.get());
    if (!c) continue;
    const Vec3 acc = c->acceleration(t);
    if (acc == Vec3::Zero()) continue;
    for (int k = 0; k < 3; ++k)
      CATENA_PETSC(VecSetValue(out, dofs_.multiplier_dof(c->index(), k), acc[k], INSERT_VALUES));
  }
  CATENA_PETSC(VecAssemblyBegin(out));
  CATENA_PETSC(VecAssemblyEnd(out));
}

}  // namespace catena::assembly
