#pragma once
// `catenary.ends: absorbing`: the catenary as a cut from a longer line. Shape finding and
// the static start treat the wires' ends as anchored (held at the first and last supports);
// a dynamic run then lets the waves that reach them leave (model::AbsorbingEnd).
#include "catena/model/model.hpp"

namespace catena::model {

// Not collective. If the model's catenary asks for absorbing ends, turns the contact wire's
// and the messenger's end supports into absorbing ends (keeping a 2D catenary's in-plane
// restraint); returns how many. Call after shape finding (which sizes the droppers on the
// anchored wires), before the dynamic run's system is built.
int absorb_catenary_ends(Model& model);

}  // namespace catena::model
