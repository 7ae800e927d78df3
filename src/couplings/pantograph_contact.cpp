#include "catena/couplings/pantograph_contact.hpp"

#include <algorithm>

namespace catena::couplings {

namespace {
constexpr int kActive = ContactPath::kActive;

// `dofs` with the head's position appended (the path's DOFs follow it).
std::vector<DofKey>& with_head(std::vector<DofKey>& dofs, int head) {
  for (int k = 0; k < 3; ++k) dofs.push_back(DofKey::node(head, k));
  return dofs;
}
}  // namespace

PantographContact::PantographContact(const model::Model& model, int index)
    : index_(index),
      contact_(model.contacts[static_cast<size_t>(index)]),
      path_(model, contact_, with_head(dofs_, contact_.head_node)) {}

void PantographContact::pattern(std::vector<std::pair<int, int>>& entries) const {
  entries.clear();
  const int n = static_cast<int>(dofs_.size());
  for (int head = 0; head < 3; ++head)
    for (int j = 0; j < n; ++j) {
      entries.emplace_back(head, j);
      if (j >= 3) entries.emplace_back(j, head);
    }
}

void PantographContact::active_dofs(double t, std::vector<int>& positions) const {
  positions.clear();
  if (!on_path(t)) return;
  for (int k = 0; k < 3; ++k) positions.push_back(k);
  path_.element_dofs(t, positions);
}

double PantographContact::force(const CouplingState& s, double* penetration) const {
  double N[kActive], D[kActive];
  path_.directions(s.t, N, D);
  double delta = 0.0, rate = 0.0;
  for (int j = 0; j < kActive; ++j) {
    delta += N[j] * s.q[j];
    rate += D[j] * s.q[j] + (s.v.empty() ? 0.0 : N[j] * s.v[j]);
  }
  if (penetration) *penetration = delta;
  if (delta <= 0.0) return 0.0;
  return std::max(0.0, contact_.stiffness * delta + contact_.damping * rate);
}

void PantographContact::evaluate(const CouplingState& s, double* f,
                                 std::span<const MatrixRequest> m, Scratch&) const {
  const double F = force(s);
  double N[kActive], D[kActive];
  path_.directions(s.t, N, D);
  if (f)
    for (int j = 0; j < kActive; ++j) f[j] = F * N[j];
  const double k = contact_.stiffness, c = contact_.damping;
  for (const MatrixRequest& r : m)
    for (int i = 0; i < kActive; ++i)
      for (int j = 0; j < kActive; ++j)
        r.out[i * kActive + j] =
            F == 0.0 ? 0.0 : N[i] * (r.c.c_K * (k * N[j] + c * D[j]) + r.c.c_C * c * N[j]);
}

}  // namespace catena::couplings
