#pragma once
// An element's properties, held once for all the elements that have the same values: the
// thousands of cable elements of a line share one block. Every rank holds every element
// description (docs/architecture.md, "The model is replicated"), and a property variant
// (144 bytes, the beam's the largest) was most of an element's 208 bytes; the handle is 16.
//
// An element whose values are its own alone (explicit elements each given their own
// unstretched length, a catenary's droppers after shape finding) pays the handle and a block
// of its own (about 180 bytes with the allocator's share) on top of its 88-byte description:
// more than the 208 bytes it took before, but such elements are few in the lines that are
// long.
//
// Read through * and ->. Write through edit(), which first gives this element a block of
// its own if others share its block, so an edit never reaches another element.
// edit_shared() edits a group of handles and keeps those that shared a block sharing one.
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

#include "catena/model/element_props.hpp"

namespace catena::model {

class SharedProps {
 public:
  // Shares one default block (an empty cable's), so that an element list resized or
  // default-constructed in bulk allocates nothing.
  SharedProps() : props_(default_block()) {}

  // From any alternative of ElementProps, or the variant itself: a block of its own.
  template <class Props>
  requires(std::is_constructible_v<ElementProps, Props&&> &&
           !std::is_same_v<std::remove_cvref_t<Props>, SharedProps>)
      SharedProps(Props&& props)  // NOLINT(google-explicit-constructor): element.props = bar;
      : props_(std::make_shared<ElementProps>(std::forward<Props>(props))) {}

  const ElementProps& operator*() const { return *props_; }
  const ElementProps* operator->() const { return props_.get(); }

  // The properties to change, this element's alone.
  ElementProps& edit() {
    if (props_.use_count() > 1) props_ = std::make_shared<ElementProps>(*props_);
    return *props_;
  }

  bool same_block(const SharedProps& other) const { return props_ == other.props_; }

 private:
  static const std::shared_ptr<ElementProps>& default_block() {
    static const std::shared_ptr<ElementProps> block = std::make_shared<ElementProps>();
    return block;
  }

  std::shared_ptr<ElementProps> props_;
};

// Applies `change(ElementProps&)` once per distinct block among the properties of
// elements[which[k]] (a list of element descriptions, by index): elements that shared a block
// before share its edited copy after (a wire's prestrain set by shape finding stays one block
// for the wire).
template <class Elements, class Change>
void edit_shared(Elements& elements, const std::vector<int>& which, Change&& change) {
  // The old handles are kept until the end, so no block's address is freed and reused
  // while the lookup compares addresses.
  std::vector<std::pair<SharedProps, SharedProps>> edited;
  for (const int index : which) {
    SharedProps& props = elements[static_cast<std::size_t>(index)].props;
    bool done = false;
    for (const auto& [before, after] : edited) {
      if (props.same_block(before)) {
        props = after;
        done = true;
        break;
      }
      if (props.same_block(after)) {  // the same element listed twice: edited already
        done = true;
        break;
      }
    }
    if (done) continue;
    SharedProps before = props;
    change(props.edit());
    edited.emplace_back(std::move(before), props);
  }
}

}  // namespace catena::model
