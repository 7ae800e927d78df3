#pragma once
// The human summary `catena check` prints: what the scene holds, how many DOFs it makes
// and how many MPI ranks it deserves.
#include <string>
#include <vector>

#include "catena/model/model.hpp"

namespace catena::model {

// Free DOFs per rank the suggestion aims at: enough work per rank for the parallel
// direct/iterative solve to beat its communication.
inline constexpr int free_dofs_per_rank_target = 20000;

// Not collective. max(1, round(free DOFs / free_dofs_per_rank_target)).
int suggested_rank_count(const Model& model);

// Not collective. Multi-line summary: node, element (per kind) and DOF (per node kind:
// beam 12, cable 6, other 3) counts, fixed and free DOFs, supports, elastic supports,
// loads, masses, the catenary (spans, dimension, element lengths, wires, stitch wires,
// droppers, clamp masses, steady arms, messenger supports), moving loads and pantographs
// (path, speed, forces, stages, contact, when each is on its path within the analysis),
// sets with their element counts and prestrain/tension, analysis and output settings,
// and the suggested rank count; then "Left out:" (what the model does not represent:
// anchor spans, what the scene leaves out or disables such as stitch wires, clamp masses
// or damping) and "warning: " lines (a pantograph or load leaving its path before the
// analysis ends, an evaluation section not traversed within the duration). `n_ranks_running` is the
// size of the communicator the check runs on, shown beside the suggestion (pass 1 if unknown).
std::string describe(const Model& model, int n_ranks_running);

// Not collective. The "warning: " lines of describe (without the prefix), for `catena run`
// to repeat what `catena check` would have said.
std::vector<std::string> scene_warnings(const Model& model);

// Not collective. `catena check --ids`: the catenary builder's droppers (span, number, x,
// design height, node ids at both ends, the wire they hang from, element id) and supports
// (x, the contact-wire and messenger node ids held there, and what each support is), one
// line each; a single line saying so for a scene without a `catenary`.
std::string describe_catenary_ids(const Model& model);

}  // namespace catena::model
