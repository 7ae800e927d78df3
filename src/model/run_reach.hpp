#pragma once
// How far along the contact wire a dynamic run goes: the farthest point any pantograph
// on the catenary's contact wire reaches by the end of `analysis.duration`. With
// `catenary: {spans: auto}` this decides the span count (docs/scene.md "catenary"), so
// that a scene models the spans its run needs and no more.
#include <string>

#include "yaml_fields.hpp"

namespace catena::model::detail {

struct RunReach {
  double farthest = 0.0;   // m along the contact wire, from its start (the first support)
  std::string pantograph;  // the one that gets there
  double duration = 0.0;   // s, analysis.duration
};

// Not collective. Reads `analysis.duration` and the pantographs' `path`, `start`, `speed`
// or `speed_kmh` from the scene root ahead of their own readers (which check them again
// in full). `why` is the field that asked (for messages): fails there when the scene has
// no dynamic analysis or no pantograph on the contact wire.
RunReach read_run_reach(const Field& scene, const Field& why);

}  // namespace catena::model::detail
