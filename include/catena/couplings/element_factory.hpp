#pragma once
// Turns the model's plain descriptions of elements and node-attached items (point masses,
// elastic supports, nodal loads) into element couplings.
#include <memory>
#include <vector>

#include "catena/couplings/element_coupling.hpp"
#include "catena/elements/matrix_arena.hpp"
#include "catena/model/model.hpp"

namespace catena::couplings {

// Not collective. The kernel of model.elements[index]; its constant matrices (Rayleigh
// damping) in `arena` when given (elements/matrix_arena.hpp), else in blocks of its own.
std::unique_ptr<elements::Element> make_element(
    const model::Model& model, int index, std::shared_ptr<elements::MatrixArena> arena = nullptr);
// Not collective. The coupling of model.elements[index], whose kernel is `element`
// (make_element; made separately so that a list's kernels can be allocated together).
std::unique_ptr<ElementCoupling> make_element_coupling(const model::Model& model, int index,
                                                       std::unique_ptr<elements::Element> element);
// Not collective. One-node couplings for every point mass, elastic support and nodal load.
std::vector<std::unique_ptr<ElementCoupling>> make_node_couplings(const model::Model& model);

}  // namespace catena::couplings
