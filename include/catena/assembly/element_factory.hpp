#pragma once
// Turns the model's plain descriptions into element kernels. Node-attached items (point
// masses, elastic supports, nodal loads) become one-node kernels so that assembly has a
// single loop.
#include <memory>
#include <vector>

#include "catena/elements/element.hpp"
#include "catena/model/model.hpp"

namespace catena::assembly {

enum class KernelOrigin { element, point_mass, elastic_support, nodal_load };

struct Kernel {
  std::unique_ptr<elements::Element> element;
  std::vector<int> nodes;  // model node indices
  KernelOrigin origin = KernelOrigin::element;
  int source = 0;          // index into the model vector the kernel came from
};

// Not collective. Kernel for model.elements[index].
Kernel make_element_kernel(const model::Model& model, int index);
// Not collective. One-node kernels for every point mass, elastic support and nodal load.
std::vector<Kernel> make_node_kernels(const model::Model& model);

}  // namespace catena::assembly
