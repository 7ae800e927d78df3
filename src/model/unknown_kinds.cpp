#include "catena/model/unknown_kinds.hpp"

#include <cstddef>

namespace catena::model {
namespace {

// One row per UnknownKind, in the enum's order (table_is_consistent below).
struct Row {
  UnknownKind kind;
  UnknownKindInfo info;
};

constexpr std::array<Row, 6> kTable{{
    {UnknownKind::point,
     {"a point node",
      "point",
      "only bars, springs, point masses or supports attach there",
      3,
      {"x", "y", "z"},
      0,
      -1,
      UpdateRule::additive,
      true}},
    {UnknownKind::ancf_cable,
     {"a cable node",
      "cable",
      "a cable attaches there",
      6,
      {"x", "y", "z", "rx_x", "rx_y", "rx_z"},
      0,
      3,
      UpdateRule::additive,
      true}},
    {UnknownKind::ancf_beam,
     {"a beam node",
      "beam",
      "a beam attaches there",
      12,
      {"x", "y", "z", "rx_x", "rx_y", "rx_z", "ry_x", "ry_y", "ry_z", "rz_x", "rz_y", "rz_z"},
      0,
      3,
      UpdateRule::additive,
      true}},
    {UnknownKind::rigid_body,
     {"a rigid body's node",
      "rigid body",
      "a rigid body sits there (its point r and its axes e1, e2, e3)",
      12,
      {"x", "y", "z", "e1_x", "e1_y", "e1_z", "e2_x", "e2_y", "e2_z", "e3_x", "e3_y", "e3_z"},
      0,
      3,
      UpdateRule::additive,
      true}},
    {UnknownKind::slider,
     {"a slider node",
      "slider",
      "a slider runs there (its point and its arc length s along its path)",
      4,
      {"x", "y", "z", "s"},
      0,
      -1,
      UpdateRule::additive,
      true}},
    {UnknownKind::multiplier,
     {"a constraint's multipliers",
      "multiplier",
      "one block per constraint",
      kMaxMultipliersPerConstraint,
      {"1", "2", "3", "4", "5", "6"},
      -1,
      -1,
      UpdateRule::additive,
      false}},
}};

// Rows in the enum's order; sizes within the widest block; position and gradients inside;
// the multiplier block as wide as a constraint's equations.
constexpr bool table_is_consistent() {
  for (std::size_t k = 0; k < kTable.size(); ++k) {
    const UnknownKindInfo& i = kTable[k].info;
    if (static_cast<std::size_t>(kTable[k].kind) != k) return false;
    if (i.size < 1 || i.size > kMaxBlockUnknowns) return false;
    if (i.position + 3 > i.size || i.gradients + 3 > i.size) return false;
    // Gradients fill the block's end in whole vectors, at most three (r_x, r_y, r_z).
    if (i.gradients >= 0 && ((i.size - i.gradients) % 3 != 0 || i.size - i.gradients > 9))
      return false;
  }
  return kTable[static_cast<std::size_t>(UnknownKind::multiplier)].info.size ==
         kMaxMultipliersPerConstraint;
}
static_assert(table_is_consistent(), "unknown-kind table: order, size or slots wrong");

// True when `inner`'s components are the first components of `outer`'s.
bool begins_with(const UnknownKindInfo& outer, const UnknownKindInfo& inner) {
  if (inner.size > outer.size) return false;
  for (int k = 0; k < inner.size; ++k)
    if (outer.components[k] != inner.components[k]) return false;
  return true;
}

}  // namespace

const UnknownKindInfo& kind_info(UnknownKind kind) {
  return kTable.at(static_cast<std::size_t>(kind)).info;
}

const std::vector<UnknownKind>& all_unknown_kinds() {
  static const std::vector<UnknownKind> kinds = [] {
    std::vector<UnknownKind> all;
    for (const Row& row : kTable) all.push_back(row.kind);
    return all;
  }();
  return kinds;
}

std::optional<UnknownKind> kind_holding_both(UnknownKind a, UnknownKind b) {
  if (a == b) return a;
  // Blocks that are not a node's (multipliers) share with nothing.
  if (!kind_info(a).nodal || !kind_info(b).nodal) return std::nullopt;
  if (begins_with(kind_info(a), kind_info(b))) return a;
  if (begins_with(kind_info(b), kind_info(a))) return b;
  return std::nullopt;
}

}  // namespace catena::model
