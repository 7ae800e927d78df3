#pragma once
// The kinds of element as output files name them: the code of a kind is its index in
// ElementProps, and the names, comma-separated in that order, come from each properties
// struct's `kind` (element_props.hpp). A file carries both, so it stays readable if kinds
// are added.
#include <array>
#include <string>
#include <string_view>
#include <variant>

#include "catena/model/model.hpp"

namespace catena::model {

// How many kinds there are; codes are 0 .. element_kind_count - 1.
inline constexpr int element_kind_count = static_cast<int>(std::variant_size_v<ElementProps>);

// Not collective.
inline int element_kind_code(const ElementProps& props) { return static_cast<int>(props.index()); }

// Not collective. The name of the kind with this code.
inline std::string_view element_kind_name_at(int code) {
  static constexpr auto names = []<class... Props>(std::variant<Props...>*) {
    return std::array<std::string_view, sizeof...(Props)>{Props::kind...};
  }(static_cast<ElementProps*>(nullptr));
  return names.at(static_cast<std::size_t>(code));
}

// Not collective. The kind's name: "cable", "beam", "bar" or "spring".
inline std::string_view element_kind_name(const ElementProps& props) {
  return std::visit([](const auto& p) -> std::string_view { return p.kind; }, props);
}

// Not collective. "cable,beam,bar,spring".
inline std::string element_kind_names() {
  return []<class... Props>(std::variant<Props...>*) {
    std::string names;
    ((names += (names.empty() ? "" : ","), names += Props::kind), ...);
    return names;
  }(static_cast<ElementProps*>(nullptr));
}

}  // namespace catena::model
