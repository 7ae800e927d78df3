#pragma once
// Per-element options shared by `lines` and explicit `elements`: a cable's prestress
// (tension, prestrain or unstretched_length, at most one) and a distributed load, each
// checked against the kind of the section it is given with.
#include <optional>
#include <string>
#include <vector>

#include "section_reader.hpp"
#include "yaml_fields.hpp"

namespace catena::model::detail {

// The keys read here, for the callers' accepted-key lists.
const std::vector<std::string>& element_option_keys();

// How a cable's prestrain ε_p is given. The element's unstretched length is
// L / (1 + ε_p) for reference (mesh) length L.
struct PrestressSpec {
  enum class Kind { none, tension, prestrain, unstretched_length };
  Kind kind = Kind::none;
  double value = 0.0;          // N (tension), − (prestrain) or m (unstretched_length)
  std::optional<Field> given;  // the key it was given at, for messages
};

// Not collective. Reads tension / prestrain / unstretched_length from a line or element
// entry. Errors if more than one is given or the section is not a cable.
PrestressSpec read_prestress(const Field& entry, const Section& section);

// Not collective. ε_p for reference length `length` (m) and axial stiffness `EA` (N):
// tension T → T/EA; unstretched length L0 → length/L0 − 1. Errors at the key the spec was
// given at if ε_p ≤ −1 (a non-positive unstretched length).
double resolve_prestrain(const PrestressSpec& spec, double EA, double length);

// Not collective. `distributed_load` (N/m, default zero); cable and beam sections only.
Vec3 read_distributed_load(const Field& entry, const Section& section);

}  // namespace catena::model::detail
