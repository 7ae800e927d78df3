#pragma once
// What each element is, for viewers and scripts: /mesh/element_kind (cable, beam, bar,
// spring) and /mesh/element_set (the scene's set: contact_wire, messenger, droppers, a
// pantograph, ...), written alike into the static result and the time series
// (mesh_layout.hpp; docs/output.md).
#include <string>
#include <vector>

#include "catena/model/model.hpp"
#include "hdf5_parallel_write.hpp"
#include "row_redistribution.hpp"

namespace catena::io {

// Not collective. The model's element set names, sorted and unique, so that the indices
// in /mesh/element_set do not depend on the order in which the scene lists its parts.
std::vector<std::string> element_set_names(const model::Model& model);

// Collective. Writes /mesh/element_kind ((n_elements,) int8, model::element_kind_code,
// attribute `kinds`: the names in code order) and /mesh/element_set ((n_elements,) int32,
// the index into the attribute `set_names`, mesh_layout::no_set for none), this rank
// writing rows `block`. Throws as write_block_dataset.
void write_element_classes(const ParallelHdf5File& file, const model::Model& model,
                           const RowBlock& block);

}  // namespace catena::io
