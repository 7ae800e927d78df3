#pragma once
// The settings of a dynamic analysis: `analysis.duration`, `analysis.initial` and the
// top-level `integrator` map (docs/scene.md). In a static scene any of them is an error,
// as are the output keys that only a time series uses.
#include "catena/model/model.hpp"
#include "yaml_fields.hpp"

namespace catena::model::detail {

// Not collective. Needs model.analysis (read_analysis) and the generated lines.
void read_dynamics(const Field& scene, Model& model);

}  // namespace catena::model::detail
