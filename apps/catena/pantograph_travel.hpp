#pragma once
// Where a pantograph is drawn. Its stage nodes move vertically only (the model holds their
// x and y: the contact point travels along the wire, not the nodes), so the time series
// would show every pantograph standing at its start in ParaView. Each sample writes them
// under their contact point instead: moved by the horizontal travel of the contact point
// along its path (on the reference geometry) since t = 0. Only the written positions move;
// the model, its state and the checkpoints do not.
#include <vector>

#include "catena/core/vec3.hpp"
#include "catena/model/model.hpp"
#include "catena/model/path_stations.hpp"

namespace catena::app {

class PantographTravel {
 public:
  // `owned_nodes`: the nodes whose positions a sample holds, 3 values each, in this order.
  PantographTravel(const model::Model& model, const std::vector<int>& owned_nodes);

  // Not collective. Moves the owned stage nodes of pantograph j in `positions` by the
  // horizontal offset of the path point at contact_position[j] from the one at its start.
  void move(const std::vector<double>& contact_position, std::vector<double>& positions) const;

 private:
  struct Pantograph {
    std::vector<int> rows;  // of its stage nodes in the sample (owned ones only)
    const std::vector<int>* elements = nullptr;
    model::PathStations stations;
    Vec3 start_point = Vec3::Zero();
    Vec3 up = Vec3::UnitZ();
  };
  const model::Model& model_;
  std::vector<Pantograph> pantographs_;
};

}  // namespace catena::app
