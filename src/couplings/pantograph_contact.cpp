#include "catena/couplings/pantograph_contact.hpp"

#include <algorithm>
#include <map>
#include <sstream>

#include "catena/core/error.hpp"
#include "catena/elements/hermite.hpp"
#include "catena/model/node_kinds.hpp"

namespace catena::couplings {

namespace {
constexpr int kActive = 15;  // head (3) + the wire element's r_A, r_A,x, r_B, r_B,x
}  // namespace

PantographContact::PantographContact(const model::Model& model, int index)
    : index_(index), contact_(model.contacts[static_cast<size_t>(index)]) {
  const std::vector<int>& path = model.paths[static_cast<size_t>(contact_.path)].elements;
  stations_ = model::path_stations(model, path);
  reach_ = model::contact_reach(model, contact_, stations_);
  for (int k = 0; k < 3; ++k) dofs_.push_back(DofKey::node(contact_.head_node, k));
  // Each node of the reach once, ascending, with its position and slope (6 DOFs).
  const std::vector<int> counts = model::all_node_dofs(model);
  std::map<int, int> first_dof;
  for (std::size_t i = 0; i < path.size(); ++i)
    if (reach_.contains(i))
      for (int node : model.elements[static_cast<size_t>(path[i])].nodes) first_dof[node] = 0;
  for (auto& [node, first] : first_dof) {
    CATENA_ASSERT(counts[static_cast<size_t>(node)] >= 6,
                  "a contact's path is made of cable or beam elements");
    first = static_cast<int>(dofs_.size());
    for (int k = 0; k < 6; ++k) dofs_.push_back(DofKey::node(node, k));
  }
  for (std::size_t i = 0; i < path.size(); ++i) {
    const std::vector<int>& nodes = model.elements[static_cast<size_t>(path[i])].nodes;
    element_a_.push_back(reach_.contains(i) ? first_dof[nodes.front()] : -1);
    element_b_.push_back(reach_.contains(i) ? first_dof[nodes.back()] : -1);
  }
}

std::size_t PantographContact::element_in_reach(double t) const {
  const double s = position(t);
  const std::size_t e = stations_.element_at(s);
  if (!reach_.contains(e)) {
    std::ostringstream os;
    os << "pantograph '" << contact_.name << "': its contact point at t = " << t << " s (" << s
       << " m along its path) is beyond the part of the path prepared for the run (from its "
          "start, speed and analysis.duration)";
    throw Error(os.str());
  }
  return e;
}

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
  const size_t e = element_in_reach(t);
  for (int k = 0; k < 3; ++k) positions.push_back(k);
  for (int first : {element_a_[e], element_b_[e]})
    for (int k = 0; k < 6; ++k) positions.push_back(first + k);
}

void PantographContact::directions(double t, double* N, double* D) const {
  const double s = position(t);
  const size_t e = element_in_reach(t);
  const double L = stations_.element_length(e);
  const elements::HermiteAt h = elements::hermite_at(std::clamp(s - stations_.start[e], 0.0, L), L);
  for (int k = 0; k < 3; ++k) {
    N[k] = contact_.up[k];
    D[k] = 0.0;
  }
  // Blocks r_A, r_A,x, r_B, r_B,x carry the shape functions S1..S4 (elements/hermite.hpp).
  for (int b = 0; b < 4; ++b)
    for (int k = 0; k < 3; ++k) {
      N[3 + 3 * b + k] = -h.s[b] * contact_.up[k];
      D[3 + 3 * b + k] = -contact_.speed * h.ds[b] * contact_.up[k];
    }
}

double PantographContact::force(const CouplingState& s, double* penetration) const {
  double N[kActive], D[kActive];
  directions(s.t, N, D);
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
  directions(s.t, N, D);
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
