#pragma once
// What the catenary builder (scene key `catenary`, docs/catenary.md) put into a Model:
// which elements are the contact wire, the messenger, the stitch wires and the droppers
// (and which wire each dropper hangs from), where the wire must be (the design heights),
// and which values shape finding (catenary/shape_finding.hpp) may change. Plain data;
// indices are 0-based positions in the Model's vectors. Units SI; z is up (the builder
// requires gravity along −z).
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace catena::model {

// One dropper from the messenger, or from a stitch wire, down to the contact wire: a bar
// (BarProps), or a chain of cable elements (CableProps, tension_only,
// prestrain_with_loads) hinged to the wires at its own end nodes.
struct CatenaryDropper {
  // Into Model::elements: the bar, or the lowest cable element (whose axial force is the
  // pull on the contact wire); `elements` lists all of them, top to bottom.
  int element = 0;
  std::vector<int> elements;
  double mesh_length = 0.0;  // m, upper node to contact-wire node in the reference
  int contact_node = 0;      // its lower node, on the contact wire
  int upper_node = 0;        // its upper node, on the messenger or on stitch wire `stitch`
  int stitch = -1;           // into CatenaryLayout::stitch_wires; −1: hangs from the messenger
  int span = 0;              // 0-based span number
  double design_z = 0.0;     // m, the contact wire's design height at the dropper
  // m: the mesh length as built; shape finding sets the length that puts the contact wire
  // at design_z (and the elements' unstretched lengths with it).
  double unstretched_length = 0.0;
  // N/m: when > 0 the dropper's stiffness EA/l0 is what the design fixes, so its EA is
  // set to stiffness × unstretched length whenever the length changes; 0: EA is fixed.
  double stiffness = 0.0;
};

// A steady arm (registration) at an intermediate support: an elastic support on the
// contact wire and, when the design height is held, a vertical preload (a nodal load)
// that shape finding sizes so that the static registration height is design_z.
struct CatenaryRegistration {
  int node = 0;            // contact-wire node, into Model::nodes
  int load = -1;           // into Model::nodal_loads; −1: the height is not held
  double design_z = 0.0;   // m
  double stiffness = 0.0;  // N/m, vertical
};

// A wire of the tension section: its cable elements in x order and its design tension
// (the axial force the balance weights keep; shape finding sets the prestrain to it).
struct CatenaryWire {
  std::string name;           // "contact_wire", "messenger" or "stitch_wires" (its set)
  std::vector<int> elements;  // into Model::elements (CableProps), in x order
  double tension = 0.0;       // N
};

// A stitch wire (Y-stitch) at an intermediate support: a cable below the messenger from a
// clamp in the span before the support to one in the span after it, each end hinged to a
// messenger node by a stiff spring (set `stitch_joints`); it is not held at the support.
// It carries the droppers strictly between its clamps.
struct CatenaryStitch {
  CatenaryWire wire;                 // its cables in x order, its installation tension
  int support = 0;                   // into CatenaryLayout::support_x (an intermediate one)
  std::array<int, 2> clamp_nodes{};  // the messenger nodes its ends are joined to, x order
};

// `spans: auto`: why the line has the spans it has (the scene gave no count).
struct AutoSpanCount {
  double reach = 0.0;      // m, the farthest point a pantograph reaches in the run
  std::string pantograph;  // the one that reaches it
  double duration = 0.0;   // s, the run's analysis.duration
  int run_out_spans = 0;   // whole spans added beyond the span that holds `reach`
};

// `catenary.window`: the model holds `spans` spans of a longer line that repeats every
// `period` spans, and follows the pantographs along it (model/catenary_window.hpp): when
// the first pantograph passes the start of span behind + period (0-based, in the
// window), the state moves back by `period` spans and the spans that enter at the front
// start from the static state. Both ends of the window are absorbing ends.
struct CatenaryWindow {
  int spans = 0;             // spans modelled
  int behind = 0;            // whole spans kept behind the span of the first pantograph
  int period = 1;            // spans after which the line repeats (2 with stagger)
  int line_spans = 0;        // spans of the line the scene describes
  double span_length = 0.0;  // m
  double span_arc = 0.0;     // m of contact-wire path per span (x unless staggered)
  int origin_span = 0;       // the line's span the window's first span is at t = 0
  // m of x and of contact-wire path one shift moves the window along the line
  double shift_x() const { return period * span_length; }
  double shift_arc() const { return period * span_arc; }
  // m, the line's path position of the window's path start at t = 0
  double origin_arc() const { return origin_span * span_arc; }
};

struct CatenaryLayout {
  int dimension = 3;              // 2: x–z plane (out-of-plane DOFs fixed), 3
  std::vector<double> support_x;  // m, the n_spans + 1 support (mast) positions
  // Per support: the node of each wire that is held there (with stagger a wire has two
  // nodes at an intermediate support, joined by a spring: the one that ends the span before).
  std::vector<int> contact_support_nodes, messenger_support_nodes;
  std::vector<double> dropper_offsets;  // m, from the span's start; empty if they differ per span
  double system_height = 0.0;           // m, messenger above contact wire at the supports
  CatenaryWire contact_wire;
  CatenaryWire messenger;
  std::vector<CatenaryStitch> stitch_wires;         // in x order; empty without `stitch`
  std::vector<CatenaryDropper> droppers;            // in x order
  std::vector<CatenaryRegistration> registrations;  // intermediate supports, in x order
  std::optional<AutoSpanCount> auto_spans;          // set when the run chose the span count
  // `ends: absorbing`: the wires' end supports become absorbing ends in a dynamic run, after
  // shape finding (model/catenary_ends.hpp); the model holds them as supports until then.
  bool absorbing_ends = false;
  std::optional<CatenaryWindow> window;  // `window`: a moving window of the line
};

}  // namespace catena::model
