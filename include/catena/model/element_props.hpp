#pragma once
// The properties of each kind of element, as its section in the scene gives them: plain
// data that describes itself. Each struct has
//   kind       its name: the section's `type` and the name in output files
//              (element_kinds.hpp);
//   node_kind  the kind of unknowns it asks for at each of its nodes (unknown_kinds.hpp;
//              a node takes the kind that holds its elements': node_kinds.hpp);
//   read_keys  its scene keys, their ranges, units and defaults, in the vocabulary of
//              scene_keys.hpp; the scene reader reads any alternative of ElementProps
//              from this alone (src/model/section_reader.cpp).
// A struct in ElementProps without any of the three does not compile (see the end).
#include <concepts>
#include <string_view>
#include <variant>

#include "catena/core/curvature_measure.hpp"
#include "catena/core/vec3.hpp"
#include "catena/model/scene_keys.hpp"
#include "catena/model/unknown_kinds.hpp"

namespace catena::model {

// Rayleigh damping D = α M + β K_ref (elements/rayleigh_damped.hpp); zero: none.
struct Rayleigh {
  double mass = 0.0;       // α, 1/s
  double stiffness = 0.0;  // β, s
  bool active() const { return mass > 0.0 || stiffness > 0.0; }
};

// ANCF gradient-deficient cable (contact wire, messenger, droppers as cables).
struct CableProps {
  static constexpr const char* kind = "cable";
  static constexpr UnknownKind node_kind = UnknownKind::ancf_cable;  // [r, r_x]
  double EA = 0.0;                                                   // N, axial stiffness
  double EI = 0.0;                                                   // N·m², bending stiffness
  double mass_per_length = 0.0;  // kg/m, per unit unstretched length
  double damping_time = 0.0;     // s, Kelvin–Voigt axial: N = EA (ε + τ ε̇)
  // Prestrain ε_p: the element's unstretched length is L_mesh / (1 + ε_p). Set from the
  // scene's `tension` (ε_p = T/EA), `prestrain` or `unstretched_length`.
  double prestrain = 0.0;
  Rayleigh rayleigh;  // proportional damping α M + β K_ref
  // Droppers as cables (catenary builder): no compression beyond a slack residue
  // (elements::AncfCable::kSlackStiffness), and the prestrain, a length found by shape
  // finding rather than a tension, put on with the loads along the static load path.
  bool tension_only = false;
  bool prestrain_with_loads = false;
  // The bending law: which curvature the bending energy squares (core/curvature_measure.hpp).
  CurvatureMeasure curvature = CurvatureMeasure::reference_length;

  // Scene keys (docs/scene.md "type: cable"); prestrain and the two flags are not section
  // keys: lines, elements and the catenary builder set them.
  template <class Keys>
  void read_keys(Keys& k) {
    k.real("EA", EA, Range::positive, "N");
    k.real("EI", EI, Range::positive, "N*m^2");
    k.real("mass_per_length", mass_per_length, Range::positive, "kg/m");
    k.real_or("damping_time", damping_time, 0.0, Range::non_negative, "s");
    k.rayleigh("rayleigh", rayleigh);
    k.choice_or("curvature", curvature, CurvatureMeasure::reference_length, kCurvatureMeasureNames);
  }
};

// ANCF beam with torsion (see elements/ancf_beam.hpp for the formulation).
struct BeamProps {
  static constexpr const char* kind = "beam";
  static constexpr UnknownKind node_kind = UnknownKind::ancf_beam;  // [r, r_x, r_y, r_z]
  double EA = 0.0;                                                  // N
  double GA_y = 0.0, GA_z = 0.0;                                    // N, shear stiffnesses
  double GJ = 0.0;                                                  // N·m², torsional stiffness
  double EI_y = 0.0, EI_z = 0.0;      // N·m², bending about the section's y and z axes
  double mass_per_length = 0.0;       // kg/m
  double rho_Iy = 0.0, rho_Iz = 0.0;  // kg·m, section rotary inertia per length
  double damping_time = 0.0;          // s, Kelvin–Voigt on all strains
  Vec3 y_axis = Vec3::UnitZ();        // reference direction of the section's y axis
  CurvatureMeasure curvature = CurvatureMeasure::reference_length;  // the bending law
  Rayleigh rayleigh;  // proportional damping α M + β K_ref (last: aggregates)

  // Scene keys (docs/scene.md "type: beam").
  template <class Keys>
  void read_keys(Keys& k) {
    k.real("EA", EA, Range::positive, "N");
    k.real("GA_y", GA_y, Range::positive, "N");
    k.real("GA_z", GA_z, Range::positive, "N");
    k.real("GJ", GJ, Range::positive, "N*m^2");
    k.real("EI_y", EI_y, Range::positive, "N*m^2");
    k.real("EI_z", EI_z, Range::positive, "N*m^2");
    k.real("mass_per_length", mass_per_length, Range::positive, "kg/m");
    k.real_or("rho_Iy", rho_Iy, 0.0, Range::non_negative, "kg*m");
    k.real_or("rho_Iz", rho_Iz, 0.0, Range::non_negative, "kg*m");
    k.real_or("damping_time", damping_time, 0.0, Range::non_negative, "s");
    k.rayleigh("rayleigh", rayleigh);
    // Only the direction matters; it is checked against each element's axis later.
    k.direction_or("y_axis", y_axis, Vec3::UnitZ());
    k.choice_or("curvature", curvature, CurvatureMeasure::reference_length, kCurvatureMeasureNames);
  }
};

// Two-node bar between node positions (droppers); optionally tension-only.
struct BarProps {
  static constexpr const char* kind = "bar";
  static constexpr UnknownKind node_kind = UnknownKind::point;  // [r]
  double EA = 0.0;                                              // N
  double mass_per_length = 0.0;                                 // kg/m, lumped half to each node
  double damping = 0.0;             // N·s/m, along the bar (c·d(length)/dt)
  double unstretched_length = 0.0;  // m; 0 = the mesh length
  bool tension_only = false;        // slack (zero force) when shorter than unstretched

  // Scene keys (docs/scene.md "type: bar").
  template <class Keys>
  void read_keys(Keys& k) {
    k.real("EA", EA, Range::positive, "N");
    k.real_or("mass_per_length", mass_per_length, 0.0, Range::non_negative, "kg/m");
    k.real_or("damping", damping, 0.0, Range::non_negative, "N*s/m");
    k.boolean_or("tension_only", tension_only, false);
    k.real_or("unstretched_length", unstretched_length, 0.0, Range::non_negative, "m");
  }
};

// Two-node linear spring–damper between node positions (zero rest length offset: the
// force is k·(x_B − x_A − (X_B − X_A)) per component, so it carries no preload).
struct SpringProps {
  static constexpr const char* kind = "spring";
  static constexpr UnknownKind node_kind = UnknownKind::point;  // [r]
  Vec3 stiffness = Vec3::Zero();                                // N/m per global axis
  Vec3 damping = Vec3::Zero();                                  // N·s/m per global axis

  // Scene keys (docs/scene.md "type: spring").
  template <class Keys>
  void read_keys(Keys& k) {
    k.spring_stiffness("stiffness", stiffness);
    k.spring_damping("damping", damping);
  }
};

// Every kind of element: its properties, its name in output files (`kind`) and the kind
// of unknowns it asks for at each of its nodes (`node_kind`).
using ElementProps = std::variant<CableProps, BeamProps, BarProps, SpringProps>;

// What every alternative of ElementProps must declare.
template <class Props>
concept DescribedElementProps = requires(Props& props, KeyNames& keys) {
  { Props::kind } -> std::convertible_to<std::string_view>;
  { Props::node_kind } -> std::convertible_to<UnknownKind>;
  props.read_keys(keys);
};

namespace props_check {
// One instantiation per alternative, so that the compiler names the struct at fault.
template <class Props>
consteval bool described() {
  static_assert(DescribedElementProps<Props>,
                "an ElementProps alternative needs `static constexpr const char* kind`, "
                "`static constexpr UnknownKind node_kind` and `template <class Keys> void "
                "read_keys(Keys&)` (element_props.hpp)");
  return true;
}
template <class... Props>
consteval bool all_described(std::variant<Props...>*) {
  return (described<Props>() && ...);
}
}  // namespace props_check
static_assert(props_check::all_described(static_cast<ElementProps*>(nullptr)));

}  // namespace catena::model
