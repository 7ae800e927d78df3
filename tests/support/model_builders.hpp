#pragma once
// Programmatic models for tests that exercise layers below the scene reader.
#include <string>
#include <vector>

#include "catena/model/model.hpp"

namespace catena::test {

// A straight line of n two-node elements from a to b with the given properties; nodes are
// appended to `m` (ids = index + 1) and the node indices returned (first to last).
std::vector<int> add_line(model::Model& m, const Vec3& a, const Vec3& b, int n_elements,
                          const model::ElementProps& props);

// Sets the nodal reference frames (tangent) from attached cable/beam elements, as the
// scene reader does.
void set_reference_frames(model::Model& m);

void pin(model::Model& m, int node);  // fix x, y, z

// The flexible pendulum of meshes/cable_pendulum.yaml (Berzeri et al.: 1.2 m, EA 1260 N,
// EI 8.505e-3 N·m², 9.972 kg/m, gravity −z) in n_elements cables: its pivot pinned, or
// (driven_pivot) held by a prescribed-motion constraint along x(t) = A (sin ωt − ωt),
// A = 0.05 m, f = 2 Hz (zero velocity and acceleration at the start).
model::Model cable_pendulum(int n_elements, bool driven_pivot);
void clamp(model::Model& m, int node);  // fix all 12 nodal DOFs (trimmed to the node's)
// Clamp as `fix: clamped` does: the position, a beam's section frame and the slope's
// direction (model::Support::slope_direction), the slope's length free.
void clamp_direction(model::Model& m, int node);

// A 60 m cable line of 24 `section` elements along x, pinned at both ends, with point
// masses of 0.195 kg at every fourth node and an elastic support at the middle node
// (300 N/m and `support_damping` N·s/m in y and z); gravity −z.
model::Model cable_line_with_items(const model::CableProps& section, double support_damping);

// Scene text: a 30 m contact wire at 20 kN (60 cables, pinned ends) with an EN 50318
// pantograph pressing 120 N at 60 m/s from `start` metres (a dynamic analysis of 1 s).
std::string pantograph_on_wire_scene(double start);

}  // namespace catena::test
