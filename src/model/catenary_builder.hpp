#pragma once
// The geometry of a simple catenary (one tension section) from its design data: nodes,
// cable elements for the contact wire, the messenger and the optional stitch wires,
// dropper bars, clamp and steady-arm masses, supports, elastic supports, the contact-wire
// path, the registration nodes and Model::catenary. The design is read and range-checked
// by catenary_reader; what is built, and why, is in docs/catenary.md.
//
// Geometry (reference configuration, stress-free apart from the cables' prestrain):
//   x along the track from the first support (x = 0), z up, y lateral;
//   contact wire straight at z = 0 between supports, messenger straight at
//   z = system_height, both at y = ±stagger alternating at the supports (3D) or y = 0;
//   a stitch wire straight between its two clamp points on the messenger.
// Both wires are straight in every span because ANCF slopes are continuous at a node. The
// droppers are vertical bars, or vertical chains of cable elements hinged to the wires, in
// the reference configuration; their unstretched lengths (the pre-sag shape) come from
// shape finding.
//
// Numbering: new node ids follow the largest id in the model (explicit and line nodes),
// contact-wire nodes first, then messenger nodes, then the stitch wires' (stitch by
// stitch), each in x order, then the cable droppers' own nodes (droppers in x order, each
// top to bottom); new element ids follow the largest element id, in the order contact
// wire, messenger, stitch wires, droppers (a cable dropper: its elements top to bottom,
// then its two hinges), joints, stitch joints.
#include <optional>
#include <utility>
#include <vector>

#include "scene_build.hpp"

namespace catena::model::detail {

struct WireDesign {
  double EA = 0.0;               // N
  double EI = 0.0;               // N·m²
  double mass_per_length = 0.0;  // kg/m
  double tension = 0.0;          // N, in the static state
  double damping_time = 0.0;     // s, Kelvin–Voigt axial damping
  Rayleigh rayleigh;             // proportional damping (none by default)
};

// How droppers are modelled (`droppers.model`): a two-node tension-only bar, its mass
// lumped at its ends, or a chain of ANCF cable elements with distributed mass, slack in
// compression, hinged to the wires (docs/catenary.md).
enum class DropperModel { bar, cable };

// A stitch wire at every intermediate support (`catenary.stitch`): clamped to the
// messenger at x_support ± length/2, carrying the droppers strictly between the clamps.
struct StitchDesign {
  double length = 0.0;  // m, between the two clamps
  WireDesign wire;      // its tension is the installation tension in the static state
};

struct DropperDesign {
  DropperModel model = DropperModel::bar;
  int cable_elements = 0;                      // per dropper, cable model only
  double EI = 0.0;                             // N·m², cable model only
  std::vector<std::vector<double>> positions;  // m from the span's start, per span
  // m, per span: the contact wire's design height at each dropper (z up, 0 at the
  // registrations): the pre-sag parabola or the scene's design sags.
  std::vector<std::vector<double>> design_z;
  double EA = 0.0;               // N; 0 when `stiffness` is given
  double stiffness = 0.0;        // N/m (EA = stiffness × unstretched length); 0 when EA is
  double mass_per_length = 0.0;  // kg/m
  double damping = 0.0;          // N·s/m, along the dropper
  bool tension_only = true;
  double clamp_mass_contact = 0.0;  // kg, the clamp on the contact wire
  double clamp_mass_upper = 0.0;    // kg, the clamp on the messenger or stitch wire
};

struct SteadyArmDesign {
  double stiffness = 0.0;          // N/m, vertical, at the contact wire's intermediate supports
  double damping = 0.0;            // N·s/m
  double mass = 0.0;               // kg
  bool hold_design_height = true;  // preload sized by shape finding
};

struct MessengerSupportDesign {
  bool fixed = false;      // z held (and y in 3D); otherwise an elastic support
  double stiffness = 0.0;  // N/m, vertical, when not fixed
  double damping = 0.0;    // N·s/m
};

// The name of the path the builder makes along the contact wire (pantographs run on it).
inline constexpr const char* kContactWirePath = "contact_wire";

struct CatenaryDesign {
  int dimension = 3;                 // 2 or 3
  std::vector<double> span_lengths;  // m
  double system_height = 0.0;        // m
  double stagger = 0.0;              // m, 3D only
  double element_length = 0.0;       // m, upper bound of the wires' element length
  WireDesign contact_wire;
  WireDesign messenger;
  DropperDesign droppers;
  SteadyArmDesign steady_arms;
  MessengerSupportDesign messenger_supports;
  std::optional<StitchDesign> stitch;                   // none: no stitch wires
  std::optional<std::pair<int, int>> evaluation_spans;  // 1-based, first ≤ last
  std::optional<AutoSpanCount> auto_spans;              // `spans: auto` (else the scene's count)
  bool absorbing_ends = false;                          // `ends: absorbing`
  double x_origin = 0.0;  // m, x of the first support (a window's place on its line)
};

// Stiffness of the spring that joins the two nodes of a wire at a staggered support (and a
// stitch wire's end to its messenger node), as a multiple of the wire's axial stiffness
// EA/h of its shortest element (h): its stretch under the wire tension is 1 % of one
// element's.
inline constexpr double kJointStiffnessFactor = 100.0;

// The same for the hinges that join a cable dropper's end nodes to the wires, as a
// multiple of the dropper's EA/h (h its element length): stiffer than the wires' joints
// because a hinge is in series with the whole dropper, whose stiffness is a design value;
// the two hinges lower it by a fraction 2h/(factor·l0) (0.02 % for two elements on a
// dropper shortened to half its mesh length).
inline constexpr double kDropperHingeStiffnessFactor = 1.0e4;

// Where the pre-sag parabola is zero (`catenary.presag_between`): at the supports, or at
// each span's first and last droppers (as in designs that hang the first and last droppers
// at the registration height).
enum class PresagBetween { supports, end_droppers };

// Not collective. The contact wire's design heights at one span's dropper positions
// (increasing, m from the span's start; two or more for end_droppers): the pre-sag parabola
// −4·presag·ξ·(1 − ξ), ξ the position's fraction of the way from one zero to the other.
std::vector<double> presag_heights(double presag, PresagBetween between,
                                   const std::vector<double>& positions, double span_length);

// Not collective. The number of elements between two stations `gap` apart: the fewest no
// longer than h.
int elements_in_gap(double gap, double h);

// Not collective. Adds the catenary to build.model (see the file comment). `entry` is the
// scene's `catenary` map, which messages about the generated nodes and elements point at.
// The design must be valid (catenary_reader checks it).
void build_catenary(const CatenaryDesign& design, const Field& entry, SceneBuild& build);

}  // namespace catena::model::detail
