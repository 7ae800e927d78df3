#include "catenary_builder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>

#include "catena/core/error.hpp"
#include "stitch_plan.hpp"

namespace catena::model::detail {
namespace {

// Support components (bit k of Support::fixed_mask, nodal layout [x, y, z, rx_x, rx_y, ...]).
constexpr unsigned kFixX = 1u << 0;
constexpr unsigned kFixY = 1u << 1;
constexpr unsigned kFixZ = 1u << 2;
constexpr unsigned kFixSlopeY = 1u << 4;  // rx_y: keeps a 2D wire's tangent in the x–z plane

// The stations of a wire, per span: its support points, dropper points and `extra` points
// (the messenger's stitch clamps), as increasing distances from the span's start. A clamp
// on a dropper point is one station.
std::vector<std::vector<double>> wire_stations(const CatenaryDesign& d,
                                               const std::vector<std::vector<double>>& extra) {
  std::vector<std::vector<double>> stations;
  for (std::size_t span = 0; span < d.span_lengths.size(); ++span) {
    std::vector<double> inner = d.droppers.positions[span];
    inner.insert(inner.end(), extra[span].begin(), extra[span].end());
    std::sort(inner.begin(), inner.end());
    inner.erase(std::unique(inner.begin(), inner.end()), inner.end());
    std::vector<double> s{0.0};
    s.insert(s.end(), inner.begin(), inner.end());
    s.push_back(d.span_lengths[span]);
    stations.push_back(std::move(s));
  }
  return stations;
}

// One wire's nodes and elements, built before anything is added to the model so that the
// numbering can follow docs/scene.md (all contact-wire nodes, then all messenger nodes).
struct WirePlan {
  std::vector<Vec3> positions;                 // new nodes, in x order
  std::vector<std::pair<int, int>> elements;   // local node numbers, in x order
  std::vector<std::vector<double>> station_s;  // per span: the stations (m from its start)
  std::vector<std::vector<int>> stations;      // per span: local node per station
  std::vector<int> support_nodes;              // per support: the node that is held
  std::vector<std::pair<int, int>> joints;     // split supports: (end, start) nodes
  std::vector<double> arc_at_support;          // m along the wire, per support
  double shortest_element = std::numeric_limits<double>::infinity();

  // The local node at station s (exactly one of station_s[span]) of span `span`.
  int node_at(std::size_t span, double s) const {
    const std::vector<double>& at = station_s[span];
    const auto k = std::find(at.begin(), at.end(), s);
    CATENA_ASSERT(k != at.end(), "not a station of the span");
    return stations[span][static_cast<std::size_t>(k - at.begin())];
  }
};

WirePlan plan_wire(const CatenaryDesign& d, const std::vector<double>& support_x, double z,
                   const std::vector<std::vector<double>>& span_stations) {
  const std::size_t n_spans = d.span_lengths.size();
  // Staggered wires kink at the intermediate supports; ANCF slopes cannot, so each span
  // gets its own node there and a stiff spring joins the two (a hinge, see the doc).
  const bool split = d.dimension == 3 && d.stagger != 0.0;
  const auto lateral = [&](std::size_t support) {
    return support % 2 == 0 ? d.stagger : -d.stagger;
  };
  WirePlan w;
  double arc = 0.0;
  auto add_node = [&](const Vec3& x) {
    w.positions.push_back(x);
    return static_cast<int>(w.positions.size()) - 1;
  };
  int previous_end = -1;
  for (std::size_t span = 0; span < n_spans; ++span) {
    const Vec3 a(support_x[span], lateral(span), z);
    const Vec3 b(support_x[span + 1], lateral(span + 1), z);
    const double length = d.span_lengths[span];
    const std::vector<double>& s = span_stations[span];
    std::vector<int> nodes_at_stations;
    int current = previous_end;
    if (span == 0 || split) {
      current = add_node(a);
      if (span > 0) w.joints.emplace_back(previous_end, current);
    }
    if (span == 0) w.support_nodes.push_back(current);
    w.arc_at_support.push_back(arc);
    nodes_at_stations.push_back(current);
    for (std::size_t k = 0; k + 1 < s.size(); ++k) {
      const int n = elements_in_gap(s[k + 1] - s[k], d.element_length);
      for (int e = 1; e <= n; ++e) {
        const double at =
            s[k] + (s[k + 1] - s[k]) * static_cast<double>(e) / static_cast<double>(n);
        const bool span_end = e == n && k + 2 == s.size();  // exactly at the next support
        const int next = add_node(span_end ? b : Vec3(a + (b - a) * (at / length)));
        const double element_length = (w.positions[next] - w.positions[current]).norm();
        w.shortest_element = std::min(w.shortest_element, element_length);
        arc += element_length;
        w.elements.emplace_back(current, next);
        current = next;
      }
      nodes_at_stations.push_back(current);
    }
    w.station_s.push_back(s);
    w.stations.push_back(nodes_at_stations);
    w.support_nodes.push_back(current);  // the end of this span holds support span + 1
    previous_end = current;
  }
  w.arc_at_support.push_back(arc);
  return w;
}

// Takes `count` ids after `last_used`; errors if int64 would overflow.
std::int64_t reserve_ids(std::int64_t& last_used, std::int64_t count, const Field& where,
                         const char* what) {
  if (last_used > std::numeric_limits<std::int64_t>::max() - count)
    where.fail(std::string("the catenary's generated ") + what +
               " ids would exceed the largest 64-bit integer; use smaller ids elsewhere");
  const std::int64_t first = last_used + 1;
  last_used += count;
  return first;
}

CableProps wire_props(const WireDesign& w) {
  CableProps p;
  p.EA = w.EA;
  p.EI = w.EI;
  p.mass_per_length = w.mass_per_length;
  p.damping_time = w.damping_time;
  p.rayleigh = w.rayleigh;
  p.prestrain = w.tension / w.EA;  // shape finding corrects it to the tension in the static state
  return p;
}

// A stitch wire's plan and where it is attached.
struct PlannedStitch {
  StitchPlan plan;
  std::size_t support = 0;     // into support_x
  std::pair<int, int> clamps;  // local messenger nodes at its first and last clamp
};

// Adds the wires, the droppers, the joints of staggered supports and of the stitch wires,
// the supports and attachments, the contact-wire path and Model::catenary.
class CatenaryAssembler {
 public:
  CatenaryAssembler(const CatenaryDesign& d, const Field& entry, SceneBuild& build)
      : d_(d), entry_(entry), build_(build), model_(build.model) {
    support_x_.push_back(d.x_origin);
    for (const double length : d.span_lengths) support_x_.push_back(support_x_.back() + length);
    const std::vector<std::vector<double>> none(d.span_lengths.size());
    const std::vector<std::vector<double>> clamps = stitch_clamp_stations(d);
    contact_ = plan_wire(d, support_x_, 0.0, wire_stations(d, none));
    messenger_ = plan_wire(d, support_x_, d.system_height, wire_stations(d, clamps));
    if (d.stitch) plan_stitches(clamps);
    origin_ = build.add_origin(entry);
  }

  void build() {
    add_nodes();
    CatenaryLayout layout;
    layout.dimension = d_.dimension;
    layout.absorbing_ends = d_.absorbing_ends;
    layout.support_x = support_x_;
    layout.system_height = d_.system_height;
    layout.auto_spans = d_.auto_spans;
    const bool same_positions =
        std::all_of(d_.droppers.positions.begin(), d_.droppers.positions.end(),
                    [&](const std::vector<double>& p) { return p == d_.droppers.positions[0]; });
    if (same_positions) layout.dropper_offsets = d_.droppers.positions[0];
    layout.contact_wire =
        add_wire("contact_wire", contact_.elements, contact_base_, d_.contact_wire);
    layout.messenger = add_wire("messenger", messenger_.elements, messenger_base_, d_.messenger);
    for (std::size_t k = 0; k < stitches_.size(); ++k) {
      CatenaryStitch stitch;
      stitch.wire =
          add_wire("stitch_wires", stitches_[k].plan.elements, stitch_base_[k], d_.stitch->wire);
      stitch.support = static_cast<int>(stitches_[k].support);
      stitch.clamp_nodes = {messenger_node(stitches_[k].clamps.first),
                            messenger_node(stitches_[k].clamps.second)};
      layout.stitch_wires.push_back(stitch);
    }
    add_droppers(layout);
    add_joints("contact_wire_joints", contact_, contact_base_, d_.contact_wire.EA);
    add_joints("messenger_joints", messenger_, messenger_base_, d_.messenger.EA);
    add_stitch_joints();
    add_supports(layout);
    add_path(layout);
    model_.catenary = std::move(layout);
  }

 private:
  int contact_node(int local) const { return contact_base_ + local; }
  int messenger_node(int local) const { return messenger_base_ + local; }

  // Stitch wire k (at support k + 1) runs straight between its clamp points on the
  // messenger, which lie on the messenger's segments on either side of the support (with
  // stagger the messenger kinks at the support; the stitch wire does not).
  void plan_stitches(const std::vector<std::vector<double>>& clamps) {
    for (std::size_t k = 0; k + 2 < support_x_.size(); ++k) {
      PlannedStitch stitch;
      stitch.support = k + 1;
      stitch.clamps = {messenger_.node_at(k, clamps[k].back()),
                       messenger_.node_at(k + 1, clamps[k + 1].front())};
      std::vector<double> dropper_x;
      for (const std::size_t span : {k, k + 1})
        for (const double s : d_.droppers.positions[span])
          if (stitch_carrying(d_, span, s) == static_cast<int>(k))
            dropper_x.push_back(contact_.positions[contact_.node_at(span, s)].x());
      stitch.plan =
          plan_stitch(messenger_.positions[stitch.clamps.first],
                      messenger_.positions[stitch.clamps.second], dropper_x, d_.element_length);
      stitches_.push_back(std::move(stitch));
    }
  }

  // Adds the nodes and reserves the ids of every element the catenary will add.
  void add_nodes() {
    std::int64_t last_id = 0;
    for (const Node& node : model_.nodes) last_id = std::max(last_id, node.id);
    std::int64_t last_element_id = 0;
    for (const ElementDesc& element : model_.elements)
      last_element_id = std::max(last_element_id, element.id);
    std::size_t n_elements = contact_.elements.size() + messenger_.elements.size() +
                             contact_.joints.size() + messenger_.joints.size();
    std::size_t n_droppers = 0;
    for (const auto& p : d_.droppers.positions) n_droppers += p.size();
    n_elements += n_droppers * static_cast<std::size_t>(elements_per_dropper());
    std::size_t n_stitch_nodes = 0;
    for (const PlannedStitch& stitch : stitches_) {
      n_elements += stitch.plan.elements.size() + 2;  // its cables and its two joints
      n_stitch_nodes += stitch.plan.positions.size();
    }
    next_element_id_ =
        reserve_ids(last_element_id, static_cast<std::int64_t>(n_elements), entry_, "element");
    const std::size_t n_dropper_nodes =
        cable_droppers() ? n_droppers * static_cast<std::size_t>(d_.droppers.cable_elements + 1)
                         : 0;
    const auto n_new = static_cast<std::int64_t>(
        contact_.positions.size() + messenger_.positions.size() + n_stitch_nodes + n_dropper_nodes);
    std::int64_t id = reserve_ids(last_id, n_new, entry_, "node");
    contact_base_ = static_cast<int>(model_.nodes.size());
    for (const Vec3& x : contact_.positions) build_.add_node(Node{id++, x}, origin_);
    messenger_base_ = static_cast<int>(model_.nodes.size());
    for (const Vec3& x : messenger_.positions) build_.add_node(Node{id++, x}, origin_);
    for (const PlannedStitch& stitch : stitches_) {
      stitch_base_.push_back(static_cast<int>(model_.nodes.size()));
      for (const Vec3& x : stitch.plan.positions) build_.add_node(Node{id++, x}, origin_);
    }
    next_dropper_node_id_ = id;  // cable droppers' own nodes: added with the droppers
  }

  bool cable_droppers() const { return d_.droppers.model == DropperModel::cable; }
  // Elements per dropper: the bar, or the cable elements and the two hinges.
  int elements_per_dropper() const { return cable_droppers() ? d_.droppers.cable_elements + 2 : 1; }

  void add_element(ElementDesc element) {
    element.id = next_element_id_++;
    build_.add_element(element, origin_);
  }

  CatenaryWire add_wire(const std::string& name, const std::vector<std::pair<int, int>>& elements,
                        int base, const WireDesign& design) {
    CatenaryWire wire{name, {}, design.tension};
    ElementDesc element;
    element.props = wire_props(design);
    element.set = name;
    for (const auto& [a, b] : elements) {
      element.nodes = {base + a, base + b};
      wire.elements.push_back(static_cast<int>(model_.elements.size()));
      add_element(element);
    }
    return wire;
  }

  void add_droppers(CatenaryLayout& layout) {
    const DropperDesign& dd = d_.droppers;
    dropper_base_ = static_cast<int>(model_.nodes.size());
    std::vector<std::size_t> carried(stitches_.size(), 0);  // droppers placed per stitch
    for (std::size_t span = 0; span < d_.span_lengths.size(); ++span) {
      for (std::size_t k = 0; k < dd.positions[span].size(); ++k) {
        const double s = dd.positions[span][k];
        const int lower = contact_node(contact_.node_at(span, s));
        const int stitch = stitch_carrying(d_, span, s);
        int upper = 0;
        if (stitch < 0) {
          upper = messenger_node(messenger_.node_at(span, s));
        } else {
          const auto j = static_cast<std::size_t>(stitch);
          upper = stitch_base_[j] + stitches_[j].plan.dropper_nodes[carried[j]++];
        }
        CatenaryDropper dropper;
        dropper.mesh_length = (model_.nodes[static_cast<std::size_t>(upper)].position -
                               model_.nodes[static_cast<std::size_t>(lower)].position)
                                  .norm();
        dropper.unstretched_length = dropper.mesh_length;
        if (cable_droppers())
          add_cable_dropper(upper, lower, dropper);
        else
          add_bar_dropper(upper, lower, dropper);
        dropper.contact_node = lower;
        dropper.upper_node = upper;
        dropper.stitch = stitch;
        dropper.span = static_cast<int>(span);
        dropper.design_z = dd.design_z[span][k];
        dropper.stiffness = dd.stiffness;
        layout.droppers.push_back(dropper);
        if (dd.clamp_mass_contact > 0.0)
          model_.point_masses.push_back(PointMass{lower, dd.clamp_mass_contact});
        if (dd.clamp_mass_upper > 0.0)
          model_.point_masses.push_back(PointMass{upper, dd.clamp_mass_upper});
      }
    }
  }

  // Mesh-length EA: a stiffness fixes EA/l0; until shape finding sets l0 it is the mesh
  // length (system_height).
  double dropper_mesh_EA() const {
    const DropperDesign& dd = d_.droppers;
    return dd.stiffness > 0.0 ? dd.stiffness * d_.system_height : dd.EA;
  }

  void add_bar_dropper(int upper, int lower, CatenaryDropper& dropper) {
    const DropperDesign& dd = d_.droppers;
    BarProps bar;
    bar.EA = dropper_mesh_EA();
    bar.mass_per_length = dd.mass_per_length;
    bar.damping = dd.damping;
    bar.tension_only = dd.tension_only;
    ElementDesc element;
    element.set = "droppers";
    element.props = bar;
    element.nodes = {upper, lower};
    dropper.element = static_cast<int>(model_.elements.size());
    dropper.elements = {dropper.element};
    add_element(element);
  }

  // Nodes from the upper wire node down to the contact-wire node (the chain's ends
  // coincide with them), cable elements between them, then a hinge at each end: a stiff
  // spring on the positions, so that the dropper's slopes stay its own (ANCF slopes are
  // shared at a node, and the dropper meets the wires at a right angle).
  void add_cable_dropper(int upper, int lower, CatenaryDropper& dropper) {
    const DropperDesign& dd = d_.droppers;
    const int n = dd.cable_elements;
    const Vec3 top_x = model_.nodes[static_cast<std::size_t>(upper)].position;
    const Vec3 bottom_x = model_.nodes[static_cast<std::size_t>(lower)].position;
    const int top = static_cast<int>(model_.nodes.size());
    for (int j = 0; j <= n; ++j)
      build_.add_node(
          Node{next_dropper_node_id_++, top_x + (bottom_x - top_x) * (static_cast<double>(j) / n)},
          origin_);
    CableProps cable;
    cable.EA = dropper_mesh_EA();
    cable.EI = dd.EI;
    cable.mass_per_length = dd.mass_per_length;
    // The dropper's damping c (N·s/m, along it) as Kelvin–Voigt: EA·τ/l0 = c; shape
    // finding keeps it so when it changes l0 or EA.
    cable.damping_time = dd.damping * dropper.mesh_length / cable.EA;
    cable.tension_only = dd.tension_only;
    cable.prestrain_with_loads = true;  // shape finding sets it: L/l0 − 1
    ElementDesc element;
    element.set = "droppers";
    element.props = cable;
    for (int j = 0; j < n; ++j) {
      element.nodes = {top + j, top + j + 1};
      dropper.elements.push_back(static_cast<int>(model_.elements.size()));
      add_element(element);
    }
    dropper.element = dropper.elements.back();
    ElementDesc hinge;
    hinge.set = "dropper_hinges";
    SpringProps spring;
    spring.stiffness =
        Vec3::Constant(kDropperHingeStiffnessFactor * cable.EA / (dropper.mesh_length / n));
    hinge.props = spring;
    hinge.nodes = {upper, top};
    add_element(hinge);
    hinge.nodes = {top + n, lower};
    add_element(hinge);
  }

  void add_joints(const std::string& set, const WirePlan& plan, int base, double EA) {
    ElementDesc element;
    element.set = set;
    SpringProps spring;
    spring.stiffness = Vec3::Constant(kJointStiffnessFactor * EA / plan.shortest_element);
    element.props = spring;
    for (const auto& [a, b] : plan.joints) {
      element.nodes = {base + a, base + b};
      add_element(element);
    }
  }

  // Each stitch wire's ends hinged to its clamp nodes on the messenger, by the same kind
  // of stiff spring as the staggered supports' joints (no Lagrange multipliers: the
  // integrators that take none stay usable).
  void add_stitch_joints() {
    if (stitches_.empty()) return;
    double shortest = std::numeric_limits<double>::infinity();
    for (const PlannedStitch& stitch : stitches_)
      shortest = std::min(shortest, stitch.plan.shortest_element);
    ElementDesc element;
    element.set = "stitch_joints";
    SpringProps spring;
    spring.stiffness = Vec3::Constant(kJointStiffnessFactor * d_.stitch->wire.EA / shortest);
    element.props = spring;
    for (std::size_t k = 0; k < stitches_.size(); ++k) {
      const int last = static_cast<int>(stitches_[k].plan.positions.size()) - 1;
      element.nodes = {messenger_node(stitches_[k].clamps.first), stitch_base_[k]};
      add_element(element);
      element.nodes = {stitch_base_[k] + last, messenger_node(stitches_[k].clamps.second)};
      add_element(element);
    }
  }

  void add_supports(CatenaryLayout& layout) {
    std::map<int, unsigned> fixed;  // node → mask, so each node gets one Support
    const unsigned planar = d_.dimension == 2 ? kFixY | kFixSlopeY : 0u;
    if (planar != 0u) {
      for (std::size_t i = 0; i < contact_.positions.size(); ++i)
        fixed[contact_node(static_cast<int>(i))] = planar;
      for (std::size_t i = 0; i < messenger_.positions.size(); ++i)
        fixed[messenger_node(static_cast<int>(i))] = planar;
      for (std::size_t k = 0; k < stitches_.size(); ++k)
        for (std::size_t i = 0; i < stitches_[k].plan.positions.size(); ++i)
          fixed[stitch_base_[k] + static_cast<int>(i)] = planar;
      for (int node = dropper_base_; node < static_cast<int>(model_.nodes.size()); ++node)
        fixed[node] = planar;  // cable droppers' own nodes
    }
    const std::size_t n_supports = support_x_.size();
    for (const std::size_t end : {std::size_t{0}, n_supports - 1}) {
      fixed[contact_node(contact_.support_nodes[end])] |= kFixX | kFixY | kFixZ;
      fixed[messenger_node(messenger_.support_nodes[end])] |= kFixX | kFixY | kFixZ;
    }
    const SteadyArmDesign& arm = d_.steady_arms;
    const MessengerSupportDesign& ms = d_.messenger_supports;
    for (std::size_t j = 1; j + 1 < n_supports; ++j) {
      const int registration = contact_node(contact_.support_nodes[j]);
      fixed[registration] |= kFixY;  // the steady arm holds the wire laterally
      if (arm.stiffness > 0.0 || arm.damping > 0.0)
        model_.elastic_supports.push_back(ElasticSupport{
            registration, Vec3(0.0, 0.0, arm.stiffness), Vec3(0.0, 0.0, arm.damping)});
      if (arm.mass > 0.0) model_.point_masses.push_back(PointMass{registration, arm.mass});
      CatenaryRegistration r;
      r.node = registration;
      r.design_z = 0.0;
      r.stiffness = arm.stiffness;
      if (arm.hold_design_height) {
        r.load = static_cast<int>(model_.nodal_loads.size());
        model_.nodal_loads.push_back(NodalLoad{registration, Vec3::Zero()});
      }
      layout.registrations.push_back(r);

      const int top = messenger_node(messenger_.support_nodes[j]);
      fixed[top] |= kFixY | (ms.fixed ? kFixZ : 0u);
      if (!ms.fixed)
        model_.elastic_supports.push_back(
            ElasticSupport{top, Vec3(0.0, 0.0, ms.stiffness), Vec3(0.0, 0.0, ms.damping)});
    }
    for (const auto& [node, mask] : fixed)
      model_.supports.push_back(Support{node, mask, false, mask & planar});
    for (std::size_t j = 0; j < n_supports; ++j) {
      layout.contact_support_nodes.push_back(contact_node(contact_.support_nodes[j]));
      layout.messenger_support_nodes.push_back(messenger_node(messenger_.support_nodes[j]));
    }
    for (const int local : contact_.support_nodes)
      model_.registration_nodes.push_back(contact_node(local));
  }

  // The contact wire as a path for moving contacts, and the evaluation section's range
  // along it (arc length on the reference geometry: x unless the wire is staggered).
  void add_path(const CatenaryLayout& layout) {
    model_.paths.push_back(ElementPath{kContactWirePath, layout.contact_wire.elements});
    if (!d_.evaluation_spans) return;
    const auto [first, last] = *d_.evaluation_spans;
    model_.evaluation_start = contact_.arc_at_support[static_cast<std::size_t>(first - 1)];
    model_.evaluation_end = contact_.arc_at_support[static_cast<std::size_t>(last)];
  }

  const CatenaryDesign& d_;
  const Field& entry_;
  SceneBuild& build_;
  Model& model_;
  std::vector<double> support_x_;
  WirePlan contact_, messenger_;
  std::vector<PlannedStitch> stitches_;  // one per intermediate support, or none
  std::vector<int> stitch_base_;         // model index of each stitch wire's first node
  int origin_ = 0;
  int contact_base_ = 0, messenger_base_ = 0;
  int dropper_base_ = 0;                   // the first cable-dropper node (none for bars)
  std::int64_t next_element_id_ = 0;       // the next element id handed out
  std::int64_t next_dropper_node_id_ = 0;  // the next cable-dropper node id
};

}  // namespace

int elements_in_gap(double gap, double h) {
  return std::max(1, static_cast<int>(std::ceil(gap / h * (1.0 - 1e-12))));
}

std::vector<double> presag_heights(double presag, PresagBetween between,
                                   const std::vector<double>& positions, double span_length) {
  const bool supports = between == PresagBetween::supports;
  const double a = supports ? 0.0 : positions.front();
  const double b = supports ? span_length : positions.back();
  std::vector<double> z;
  for (const double s : positions) {
    const double xi = (s - a) / (b - a);
    z.push_back(-4.0 * presag * xi * (1.0 - xi));
  }
  return z;
}

void build_catenary(const CatenaryDesign& design, const Field& entry, SceneBuild& build) {
  CatenaryAssembler(design, entry, build).build();
}

}  // namespace catena::model::detail
