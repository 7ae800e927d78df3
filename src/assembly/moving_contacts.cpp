// SecondOrderSystem, part: moving contacts, pantograph heads on a wire (docs/formulation.md;
// the class: include/catena/assembly/second_order_system.hpp).
#include <algorithm>
#include <cmath>
#include <memory>

#include "catena/assembly/petsc_call.hpp"
#include "catena/assembly/second_order_system.hpp"
#include "catena/elements/hermite.hpp"
#include "local_array.hpp"

namespace catena::assembly {

using detail::LocalArrayRead;

bool SecondOrderSystem::contact_geometry(const LocalContact& lc, double t,
                                         ContactGeometry& g) const {
  const model::MovingContact& c = model_->contacts[static_cast<size_t>(lc.index)];
  const std::vector<int>& path = model_->paths[static_cast<size_t>(c.path)].elements;
  const double s = c.start + c.speed * t;
  g.position = s;
  if (s < 0.0 || s > lc.start.back()) return false;
  const auto it = std::upper_bound(lc.start.begin() + 1, lc.start.end() - 1, s);
  const size_t e = static_cast<size_t>(it - lc.start.begin()) - 1;
  const double L = lc.start[e + 1] - lc.start[e];
  const elements::HermiteAt h = elements::hermite_at(std::clamp(s - lc.start[e], 0.0, L), L);
  const auto& nodes = model_->elements[static_cast<size_t>(path[e])].nodes;
  auto set = [&](int slot, int node, int k, double n, double d) {
    g.local[slot] = dofs_.local_dof(node, k);
    g.global[slot] = dofs_.global_dof(node, k);
    g.fixed[slot] = node_reference_[12 * static_cast<size_t>(node) + k];
    g.N[slot] = n;
    g.D[slot] = d;
  };
  for (int k = 0; k < 3; ++k) set(k, c.head_node, k, c.up[k], 0.0);
  // r_wire(s) = S1 r_A + S2 r_A,x + S3 r_B + S4 r_B,x; δ = (r_head − r_wire)·up, and the
  // contact point moves along the wire at `speed`: d/dt r_wire = Σ S v + speed Σ S' r.
  const int node_of_block[4] = {nodes.front(), nodes.front(), nodes.back(), nodes.back()};
  for (int b = 0; b < 4; ++b)
    for (int k = 0; k < 3; ++k)
      set(3 + 3 * b + k, node_of_block[b], 3 * (b % 2) + k, -h.s[b] * c.up[k],
          -c.speed * h.ds[b] * c.up[k]);
  return true;
}

double SecondOrderSystem::contact_force(const model::MovingContact& c, const ContactGeometry& g,
                                        const double* q, const double* v,
                                        double* penetration) const {
  double delta = 0.0, rate = 0.0;
  for (int j = 0; j < 15; ++j) {
    const double x = g.local[j] >= 0 ? q[g.local[j]] : g.fixed[j];
    delta += g.N[j] * x;
    rate += g.D[j] * x + (v && g.local[j] >= 0 ? g.N[j] * v[g.local[j]] : 0.0);
  }
  if (penetration) *penetration = delta;
  if (delta <= 0.0) return 0.0;
  return std::max(0.0, c.stiffness * delta + c.damping * rate);
}

void SecondOrderSystem::add_contact_forces(double t, const double* q, const double* v,
                                           double* f) const {
  ContactGeometry g;
  for (const LocalContact& lc : contacts_) {
    if (!contact_geometry(lc, t, g)) continue;
    const double F = contact_force(model_->contacts[static_cast<size_t>(lc.index)], g, q, v);
    if (F == 0.0) continue;
    for (int j = 0; j < 15; ++j)
      if (g.local[j] >= 0) f[g.local[j]] += F * g.N[j];
  }
}

void SecondOrderSystem::add_contact_entries(double t, const double* q, const double* v,
                                            double c_K, double c_C, Mat J) const {
  ContactGeometry g;
  for (const LocalContact& lc : contacts_) {
    const model::MovingContact& c = model_->contacts[static_cast<size_t>(lc.index)];
    // The whole head–path coupling, so that the pattern does not depend on s(t).
    for (int k = 0; k < 3; ++k) {
      const PetscInt head = dofs_.global_dof(c.head_node, k);
      if (head < 0) continue;
      for (PetscInt p : lc.path_global) {
        CATENA_PETSC(MatSetValue(J, head, p, 0.0, ADD_VALUES));
        CATENA_PETSC(MatSetValue(J, p, head, 0.0, ADD_VALUES));
      }
    }
    if (!contact_geometry(lc, t, g) || contact_force(c, g, q, v) == 0.0) continue;
    // F = k δ + c δ̇ with δ = N·q, δ̇ = N·v + D·q; f_i = F N_i:
    //   K_ij = N_i (k N_j + c D_j),  C_ij = c N_i N_j.
    PetscInt idx[15];
    double block[15 * 15];
    int n = 0;
    int slot[15];
    for (int j = 0; j < 15; ++j)
      if (g.global[j] >= 0) {
        slot[n] = j;
        idx[n++] = g.global[j];
      }
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b) {
        const int i = slot[a], j = slot[b];
        block[a * n + b] = g.N[i] * (c_K * (c.stiffness * g.N[j] + c.damping * g.D[j]) +
                                     c_C * c.damping * g.N[j]);
      }
    CATENA_PETSC(MatSetValues(J, n, idx, n, idx, block, ADD_VALUES));
  }
}

std::vector<SecondOrderSystem::ContactState> SecondOrderSystem::contact_states(
    const EvalPoint& p) {
  const size_t n = model_->contacts.size();
  std::vector<double> local(4 * n, 0.0), global(4 * n, 0.0);
  if (n == 0) return {};
  scatter_to_local(p.q, q_work_.get());
  if (p.v) scatter_to_local(p.v, v_work_.get());
  {
    const LocalArrayRead q(q_work_.get());
    std::unique_ptr<LocalArrayRead> v;
    if (p.v) v = std::make_unique<LocalArrayRead>(v_work_.get());
    ContactGeometry g;
    for (const LocalContact& lc : contacts_) {
      const size_t i = static_cast<size_t>(lc.index);
      const bool on = contact_geometry(lc, p.t, g);
      double delta = 0.0;
      const double F = on ? contact_force(model_->contacts[i], g, q.data(),
                                          v ? v->data() : nullptr, &delta)
                          : 0.0;
      local[4 * i] = F;
      local[4 * i + 1] = g.position;
      local[4 * i + 2] = delta;
      local[4 * i + 3] = on ? 1.0 : 0.0;
    }
  }
  MPI_Allreduce(local.data(), global.data(), static_cast<int>(global.size()), MPI_DOUBLE, MPI_SUM,
                comm_);
  std::vector<ContactState> out(n);
  for (size_t i = 0; i < n; ++i)
    out[i] = {global[4 * i], global[4 * i + 1], global[4 * i + 2], global[4 * i + 3] > 0.5};
  return out;
}

}  // namespace catena::assembly
