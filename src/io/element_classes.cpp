#include "element_classes.hpp"

#include <algorithm>
#include <cstdint>

#include "catena/model/element_kinds.hpp"
#include "hdf5_attributes.hpp"
#include "mesh_layout.hpp"

namespace catena::io {

std::vector<std::string> element_set_names(const model::Model& model) {
  std::vector<std::string> names;
  for (const model::ElementDesc& element : model.elements)
    if (!element.set.empty()) names.push_back(element.set);
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  return names;
}

void write_element_classes(const ParallelHdf5File& file, const model::Model& model,
                           const RowBlock& block) {
  const auto n_elements = static_cast<std::int64_t>(model.elements.size());
  const auto element = [&](std::int64_t k) -> const model::ElementDesc& {
    return model.elements[static_cast<std::size_t>(block.begin + k)];
  };
  std::vector<std::int8_t> kinds;
  for (std::int64_t k = 0; k < block.count; ++k)
    kinds.push_back(static_cast<std::int8_t>(model::element_kind_code(*element(k).props)));
  const DatasetHandle kind_dataset = write_block_dataset<std::int8_t>(
      file, {mesh_layout::element_kind, n_elements, 1}, block, kinds);
  write_string_attribute({kind_dataset.get(), file.path()}, "kinds", model::element_kind_names());

  const std::vector<std::string> set_names = element_set_names(model);
  std::vector<std::int32_t> sets;
  for (std::int64_t k = 0; k < block.count; ++k) {
    const std::string& set = element(k).set;
    sets.push_back(set.empty() ? mesh_layout::no_set
                               : static_cast<std::int32_t>(
                                     std::lower_bound(set_names.begin(), set_names.end(), set) -
                                     set_names.begin()));
  }
  const DatasetHandle set_dataset = write_block_dataset<std::int32_t>(
      file, {mesh_layout::element_set, n_elements, 1}, block, sets);
  write_string_list_attribute({set_dataset.get(), file.path()}, "set_names", set_names);
}

}  // namespace catena::io
