#pragma once
// What makes two runs "the same run" for a restart: the scene after its --set overrides,
// less the keys a restart may change. A checkpoint stores this text; `catena run --restart`
// continues a checkpoint only if its scene gives the same text, so a checkpoint left by
// another scene (or the same scene with other overrides) is never spliced into this run.
//
// Keys a restart may change: analysis.duration (a restart extends a run), output.file
// (the checkpoint is found by it anyway), output.flush_wall_seconds and
// output.checkpoint_wall_seconds (when to write, not what). Everything else — the model,
// the integrator, the output interval — must match.
#include <string>

namespace catena::model {

// Not collective. The canonical text (YAML re-emitted without comments, in the scene's key
// order) of the scene text `source_text` (Model::source_text) without the keys above.
std::string scene_identity(const std::string& source_text);

// Not collective. "" if the two identities are equal, else the first difference by key
// path: "integrator.alpha: '-0.1' here, '-0.2' in the checkpoint".
std::string first_identity_difference(const std::string& here, const std::string& there);

}  // namespace catena::model
