#include "catena/couplings/coupling.hpp"

namespace catena::couplings {

void Coupling::pattern(std::vector<std::pair<int, int>>& entries) const {
  entries.clear();
  const int n = static_cast<int>(dofs_.size());
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) entries.emplace_back(i, j);
}

void Coupling::active_dofs(double, std::vector<int>& positions) const {
  positions.resize(dofs_.size());
  for (size_t i = 0; i < positions.size(); ++i) positions[i] = static_cast<int>(i);
}

void Coupling::active_dofs_at(double t, const DofValues&, std::vector<int>& positions) const {
  active_dofs(t, positions);
}

}  // namespace catena::couplings
