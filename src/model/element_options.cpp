#include "element_options.hpp"

#include <array>
#include <cmath>
#include <variant>

#include "catena/model/element_kinds.hpp"
#include "physical_bounds.hpp"

namespace catena::model::detail {
namespace {

struct PrestressKey {
  const char* name;
  PrestressSpec::Kind kind;
};

constexpr std::array<PrestressKey, 3> prestress_keys{{
    {"tension", PrestressSpec::Kind::tension},
    {"prestrain", PrestressSpec::Kind::prestrain},
    {"unstretched_length", PrestressSpec::Kind::unstretched_length},
}};

RealRange range_of(PrestressSpec::Kind kind) {
  switch (kind) {
    case PrestressSpec::Kind::tension:
      return RealRange::any("N");
    case PrestressSpec::Kind::prestrain:
      return RealRange::any("");  // > -1: see below
    case PrestressSpec::Kind::unstretched_length:
      return RealRange::positive("m");
    case PrestressSpec::Kind::none:
      break;
  }
  return RealRange::any("");
}

}  // namespace

const std::vector<std::string>& element_option_keys() {
  static const std::vector<std::string> keys{"tension", "prestrain", "unstretched_length",
                                             "distributed_load"};
  return keys;
}

PrestressSpec read_prestress(const Field& entry, const Section& section) {
  PrestressSpec spec;
  std::string given_key;
  for (const PrestressKey& key : prestress_keys) {
    const Field field = entry.child(key.name);
    if (!field.present()) continue;
    if (!std::holds_alternative<CableProps>(section.props)) {
      const std::string hint = std::holds_alternative<BarProps>(section.props)
                                   ? " (a bar's unstretched_length belongs in its section)"
                                   : "";
      field.fail("'" + std::string(key.name) + "' applies only to cable sections; section '" +
                 section.name + "' is a " + std::string(element_kind_name(section.props)) + hint);
    }
    if (spec.given)
      entry.fail("both '" + given_key + "' and '" + key.name +
                 "' are given; at most one of tension, prestrain, unstretched_length "
                 "sets a cable's prestrain");
    spec.kind = key.kind;
    spec.value = field.real(range_of(key.kind));
    spec.given = field;
    given_key = key.name;
  }
  if (spec.kind == PrestressSpec::Kind::prestrain && !(spec.value > -1.0))
    spec.given->fail("prestrain " + format_number(spec.value) +
                     " is <= -1: the unstretched length L/(1 + prestrain) would not be "
                     "positive; expected a finite number > -1");
  return spec;
}

namespace {

// A prestrain derived from a tiny unstretched length (or EA) is as absurd as one written
// directly: it is held to the same physical bound.
double bounded_prestrain(const PrestressSpec& spec, double prestrain, const std::string& how) {
  const double bound = physical_magnitude_bound("");
  if (!(std::abs(prestrain) <= bound))
    spec.given->fail(how + " gives prestrain " + format_number(prestrain) +
                     "; its magnitude must be at most " + format_number(bound) +
                     " (a physical bound, docs/scene.md \"Physical bounds\")");
  return prestrain;
}

}  // namespace

double resolve_prestrain(const PrestressSpec& spec, double EA, double length) {
  switch (spec.kind) {
    case PrestressSpec::Kind::none:
      return 0.0;
    case PrestressSpec::Kind::prestrain:
      return spec.value;  // range-checked when read
    case PrestressSpec::Kind::unstretched_length:
      return bounded_prestrain(spec, length / spec.value - 1.0,
                               "unstretched_length " + format_number(spec.value) +
                                   " m on a chord of " + format_number(length) + " m");
    case PrestressSpec::Kind::tension: {
      const double prestrain = spec.value / EA;
      if (!(prestrain > -1.0))
        spec.given->fail("tension " + format_number(spec.value) +
                         " N gives prestrain T/EA = " + format_number(prestrain) +
                         ", which is <= -1 (no positive unstretched length); expected "
                         "tension > -EA = " +
                         format_number(-EA) + " N");
      return bounded_prestrain(
          spec, prestrain,
          "tension " + format_number(spec.value) + " N with EA " + format_number(EA) + " N");
    }
  }
  return 0.0;
}

Vec3 read_distributed_load(const Field& entry, const Section& section) {
  const Field load = entry.child("distributed_load");
  if (!load.present()) return Vec3::Zero();
  if (!std::holds_alternative<CableProps>(section.props) &&
      !std::holds_alternative<BeamProps>(section.props))
    load.fail("distributed_load applies only to cable and beam sections; section '" + section.name +
              "' is a " + std::string(element_kind_name(section.props)) + " (use nodal loads)");
  return load.vec3(RealRange::any("N/m"));
}

}  // namespace catena::model::detail
