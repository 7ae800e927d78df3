#include "catena/couplings/moving_load.hpp"

#include <algorithm>

#include "catena/core/error.hpp"
#include "catena/elements/hermite.hpp"
#include "catena/model/node_kinds.hpp"

namespace catena::couplings {

MovingLoad::MovingLoad(const model::Model& model, const model::MovingLoad& load,
                       const std::vector<bool>& evaluated)
    : load_(load), stations_(model::path_stations(model, load.elements)) {
  CATENA_ASSERT(evaluated.size() == load.elements.size(), "one flag per path element");
  for (size_t i = 0; i < load.elements.size(); ++i) {
    if (!evaluated[i]) {
      first_dof_.push_back(-1);
      continue;
    }
    const model::ElementDesc& e = model.elements[static_cast<size_t>(load.elements[i])];
    CATENA_ASSERT(model::element_node_dofs(*e.props) >= 6,
                  "a moving load's path is made of cable or beam elements");
    first_dof_.push_back(static_cast<int>(dofs_.size()));
    for (int node : {e.nodes.front(), e.nodes.back()})
      for (int k = 0; k < 6; ++k) dofs_.push_back(DofKey::node(node, k));
  }
}

int MovingLoad::element_at(double t) const {
  const double s = position(t);
  if (t < load_.start_time || !stations_.contains(s)) return -1;
  return first_dof_[stations_.element_at(s)] >= 0 ? static_cast<int>(stations_.element_at(s)) : -1;
}

void MovingLoad::active_dofs(double t, std::vector<int>& positions) const {
  positions.clear();
  const int e = element_at(t);
  if (e < 0) return;
  for (int i = 0; i < 12; ++i) positions.push_back(first_dof_[static_cast<size_t>(e)] + i);
}

void MovingLoad::evaluate(const CouplingState& s, double* f, std::span<const MatrixRequest> m,
                          Scratch&) const {
  for (const MatrixRequest& r : m) std::fill(r.out, r.out + 144, 0.0);
  if (!f) return;
  const int e = element_at(s.t);
  CATENA_ASSERT(e >= 0, "MovingLoad evaluated off its active elements");
  const double L = stations_.element_length(static_cast<size_t>(e));
  const double x = std::clamp(position(s.t) - stations_.start[static_cast<size_t>(e)], 0.0, L);
  const elements::HermiteAt h = elements::hermite_at(x, L);
  for (int a = 0; a < 4; ++a)
    for (int d = 0; d < 3; ++d) f[3 * a + d] = -(h.s[a] * load_.force[d]);
}

}  // namespace catena::couplings
