#pragma once
// Writes the /catenary group (catenary_output_layout.hpp) into a result file.
#include "catena/model/model.hpp"
#include "hdf5_parallel_write.hpp"

namespace catena::io {

// Collective. For a model with a catenary (Model::catenary): creates /catenary and writes
// its datasets, rank 0 holding every row (they are small); otherwise does nothing.
void write_catenary_layout(const ParallelHdf5File& file, const model::Model& model);

}  // namespace catena::io
