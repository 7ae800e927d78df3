#pragma once
// The scene's `analysis` (which problem to solve and the solver's load stepping and Newton
// settings) and `output` (where results go). Both optional; defaults in model.hpp.
#include "catena/model/model.hpp"
#include "yaml_fields.hpp"

namespace catena::model::detail {

// Not collective. Reads `analysis`'s type and static settings into `options` (absent keys
// keep their defaults); the dynamic keys are read by read_dynamics (dynamics_reader.hpp).
AnalysisType read_analysis(const Field& analysis, StaticOptions& options);

// Not collective. Reads `output` into `options`.
void read_output(const Field& output, OutputOptions& options);

}  // namespace catena::model::detail
