#include "catena/couplings/contact_path.hpp"

#include <algorithm>
#include <map>
#include <sstream>

#include "catena/core/error.hpp"
#include "catena/elements/hermite.hpp"
#include "catena/model/node_kinds.hpp"

namespace catena::couplings {

ContactPath::ContactPath(const model::Model& model, const model::MovingContact& contact,
                         std::vector<DofKey>& dofs)
    : contact_(contact) {
  const std::vector<int>& path = model.paths[static_cast<size_t>(contact_.path)].elements;
  stations_ = model::path_stations(model, path);
  reach_ = model::contact_reach(model, contact_, stations_);
  first_ = static_cast<int>(dofs.size());
  // Each node of the reach once, ascending, with its position and slope (6 DOFs).
  const std::vector<int> counts = model::all_node_dofs(model);
  std::map<int, int> first_dof;
  for (std::size_t i = 0; i < path.size(); ++i)
    if (reach_.contains(i))
      for (int node : model.elements[static_cast<size_t>(path[i])].nodes) first_dof[node] = 0;
  for (auto& [node, first] : first_dof) {
    CATENA_ASSERT(counts[static_cast<size_t>(node)] >= 6,
                  "a contact's path is made of cable or beam elements");
    first = static_cast<int>(dofs.size());
    for (int k = 0; k < 6; ++k) dofs.push_back(DofKey::node(node, k));
  }
  end_ = static_cast<int>(dofs.size());
  for (std::size_t i = 0; i < path.size(); ++i) {
    const auto& nodes = model.elements[static_cast<size_t>(path[i])].nodes;
    element_a_.push_back(reach_.contains(i) ? first_dof[nodes.front()] : -1);
    element_b_.push_back(reach_.contains(i) ? first_dof[nodes.back()] : -1);
  }
}

std::size_t ContactPath::element_in_reach(double t) const {
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

void ContactPath::element_dofs(double t, std::vector<int>& positions) const {
  const size_t e = element_in_reach(t);
  for (int first : {element_a_[e], element_b_[e]})
    for (int k = 0; k < 6; ++k) positions.push_back(first + k);
}

void ContactPath::directions(double t, double* N, double* D, double* E) const {
  const double s = position(t);
  const size_t e = element_in_reach(t);
  const double L = stations_.element_length(e);
  const elements::HermiteAt h = elements::hermite_at(std::clamp(s - stations_.start[e], 0.0, L), L);
  const double v = contact_.speed;
  for (int k = 0; k < 3; ++k) {
    N[k] = contact_.up[k];
    D[k] = 0.0;
    if (E) E[k] = 0.0;
  }
  // Blocks r_A, r_A,x, r_B, r_B,x carry the shape functions S1..S4 (elements/hermite.hpp).
  for (int b = 0; b < 4; ++b)
    for (int k = 0; k < 3; ++k) {
      N[3 + 3 * b + k] = -h.s[b] * contact_.up[k];
      D[3 + 3 * b + k] = -v * h.ds[b] * contact_.up[k];
      if (E) E[3 + 3 * b + k] = -v * v * h.dds[b] * contact_.up[k];
    }
}

}  // namespace catena::couplings
