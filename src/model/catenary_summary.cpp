// The catenary part of the `catena check` summary: what the builder made from the
// design data (docs/catenary.md) and what it leaves out. Everything is read back from
// the model itself (elements, point masses, supports), not from the scene text, so the
// summary shows what will be simulated.
#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "catena/model/path_stations.hpp"
#include "number_format.hpp"
#include "summary_table.hpp"

namespace catena::model::detail {
namespace {

// "0.2 kg" or "0.2 to 0.5 kg" over values (none: "none").
std::string range_text(std::vector<double> values, const std::string& unit) {
  if (values.empty()) return "none";
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  // Equal up to round-off (element lengths from node coordinates): one value.
  if (*hi - *lo <= 1e-9 * std::max(std::abs(*lo), std::abs(*hi)))
    return cat(format_number(*lo), " ", unit);
  return cat(format_number(*lo), " to ", format_number(*hi), " ", unit);
}

double point_mass_at(const Model& m, int node) {
  double mass = 0.0;
  for (const PointMass& p : m.point_masses)
    if (p.node == node) mass += p.mass;
  return mass;
}

// The vertical elastic support at a node (stiffness, damping), zero if none.
std::pair<double, double> vertical_support(const Model& m, int node) {
  double k = 0.0, c = 0.0;
  for (const ElasticSupport& s : m.elastic_supports)
    if (s.node == node) {
      k += s.stiffness.z();
      c += s.damping.z();
    }
  return {k, c};
}

const CableProps& wire_props(const Model& m, const CatenaryWire& wire) {
  return std::get<CableProps>(*m.elements[static_cast<std::size_t>(wire.elements.front())].props);
}

std::string wire_text(const Model& m, const CatenaryWire& wire) {
  const CableProps& p = wire_props(m, wire);
  std::vector<double> lengths;
  for (const int e : wire.elements) lengths.push_back(element_chord(m, e));
  return cat(plural(static_cast<long long>(wire.elements.size()), "cable"), " of ",
             range_text(lengths, "m"), ", tension ", format_number(wire.tension), " N, EA ",
             format_number(p.EA), " N, EI ", format_number(p.EI), " N*m^2, ",
             format_number(p.mass_per_length), " kg/m, damping_time ",
             format_number(p.damping_time), " s",
             p.rayleigh.active() ? cat(", Rayleigh alpha ", format_number(p.rayleigh.mass),
                                       " 1/s, beta ", format_number(p.rayleigh.stiffness), " s")
                                 : std::string());
}

// "3 x 60 m" for equal spans, else "60, 60, 55 m".
std::string spans_text(const std::vector<double>& spans) {
  if (std::all_of(spans.begin(), spans.end(), [&](double l) { return l == spans.front(); }))
    return cat(std::to_string(spans.size()), " x ", format_number(spans.front()), " m");
  std::string text;
  for (const double l : spans) text += cat(text.empty() ? "" : ", ", format_number(l));
  return cat(text, " m");
}

// The stitch wires: how many, their length between clamps, the droppers they carry, their
// cables (all of them, one section) and how they are attached.
std::string stitch_text(const Model& m, const CatenaryLayout& c) {
  CatenaryWire all{"stitch_wires", {}, c.stitch_wires.front().wire.tension};
  std::vector<double> lengths;
  for (const CatenaryStitch& s : c.stitch_wires) {
    all.elements.insert(all.elements.end(), s.wire.elements.begin(), s.wire.elements.end());
    lengths.push_back((m.nodes[static_cast<std::size_t>(s.clamp_nodes[1])].position -
                       m.nodes[static_cast<std::size_t>(s.clamp_nodes[0])].position)
                          .norm());
  }
  const auto carried = std::count_if(c.droppers.begin(), c.droppers.end(),
                                     [](const CatenaryDropper& d) { return d.stitch >= 0; });
  return cat(std::to_string(c.stitch_wires.size()), " (one per intermediate support), ",
             range_text(lengths, "m"), " between the clamps, carrying ",
             plural(static_cast<long long>(carried), "dropper"),
             ", ends hinged to the "
             "messenger (springs, set stitch_joints); ",
             wire_text(m, all));
}

struct Messenger {
  int n_fixed = 0;  // intermediate supports held in z
  std::vector<double> stiffness, damping;
};

// The messenger's intermediate supports: its nodes at the masts' x (both nodes of a
// staggered pair), held in z by a support or by a vertical elastic support.
Messenger messenger_supports(const Model& m, const CatenaryLayout& c) {
  std::set<int> nodes;
  for (const int e : c.messenger.elements)
    for (const int n : m.elements[static_cast<std::size_t>(e)].nodes)
      for (std::size_t j = 1; j + 1 < c.support_x.size(); ++j)
        if (std::abs(m.nodes[static_cast<std::size_t>(n)].position.x() - c.support_x[j]) < 1e-9)
          nodes.insert(n);
  Messenger out;
  for (const Support& s : m.supports)
    if (nodes.contains(s.node) && (s.fixed_mask & 0b100u) != 0u) ++out.n_fixed;
  for (const ElasticSupport& s : m.elastic_supports)
    if (nodes.contains(s.node)) {
      out.stiffness.push_back(s.stiffness.z());
      out.damping.push_back(s.damping.z());
    }
  return out;
}

// What a dropper is made of, bar or cable chain (EI 0 for a bar); damping in N·s/m along
// the dropper (a cable's Kelvin–Voigt time as c = EA·τ/l0).
struct DropperProperties {
  bool tension_only = false;
  double EA = 0.0, EI = 0.0, mass_per_length = 0.0, damping = 0.0;
};

DropperProperties dropper_properties(const Model& m, const CatenaryDropper& d) {
  const ElementDesc& element = m.elements[static_cast<std::size_t>(d.element)];
  if (const auto* bar = std::get_if<BarProps>(&*element.props))
    return {bar->tension_only, bar->EA, 0.0, bar->mass_per_length, bar->damping};
  const auto& cable = std::get<CableProps>(*element.props);
  const double l0 = d.mesh_length / (1.0 + cable.prestrain);
  return {cable.tension_only, cable.EA, cable.EI, cable.mass_per_length,
          cable.EA * cable.damping_time / l0};
}

}  // namespace

void describe_catenary(const Model& m, SummaryTable& t, SummaryNotes& notes) {
  const CatenaryLayout& c = *m.catenary;
  const std::size_t n_spans = c.support_x.size() - 1;
  std::vector<double> spans;
  for (std::size_t j = 0; j < n_spans; ++j) spans.push_back(c.support_x[j + 1] - c.support_x[j]);
  t.row("catenary",
        cat(std::to_string(c.dimension), "D simple catenary, ",
            plural(static_cast<long long>(n_spans), "span"), " over ",
            format_number(c.support_x.back() - c.support_x.front()), " m, ",
            plural(static_cast<long long>(c.droppers.size()), "dropper"), ", ",
            plural(static_cast<long long>(c.registrations.size()), "steady arm"), ", ",
            c.stitch_wires.empty()
                ? std::string("no stitch wires")
                : plural(static_cast<long long>(c.stitch_wires.size()), "stitch wire")));
  double stagger = 0.0;
  for (const int n : m.registration_nodes)
    stagger = std::max(stagger, std::abs(m.nodes[static_cast<std::size_t>(n)].position.y()));
  if (c.window) {
    const CatenaryWindow& w = *c.window;
    t.row("window",
          cat(plural(w.spans, "span"), " of a line of ", plural(w.line_spans, "span"), " (",
              format_number(w.line_spans * w.span_length), " m), starting at span ",
              std::to_string(w.origin_span + 1), " of the line; it moves ",
              plural(w.period, "span"), " ahead whenever the first pantograph passes span ",
              std::to_string(w.behind + w.period + 1), " of it (", plural(w.behind, "span"),
              " kept behind); every span takes the middle span's dropper lengths"),
          4);
  }
  if (c.auto_spans) {
    const AutoSpanCount& a = *c.auto_spans;
    t.row("span count",
          cat("auto: pantograph '", a.pantograph, "' reaches ", format_number(a.reach), " m in ",
              format_number(a.duration), " s, + ", plural(a.run_out_spans, "run-out span")),
          4);
  }
  t.row("spans",
        cat(spans_text(spans), ", system height ", format_number(c.system_height), " m, ",
            c.dimension == 2 ? std::string("2D (x-z plane: y and slope y fixed)")
                             : cat("3D, stagger +/-", format_number(stagger), " m")),
        4);
  t.row("contact wire", wire_text(m, c.contact_wire), 4);
  t.row("messenger", wire_text(m, c.messenger), 4);
  if (!c.stitch_wires.empty()) t.row("stitch wires", stitch_text(m, c), 4);

  // Droppers, read back from their elements (bars or cable chains).
  bool all_tension_only = true, any_tension_only = false;
  std::vector<double> dropper_mass, dropper_damping, stiffness, EA, EI, lower_clamps, upper_clamps,
      design_sags;
  for (const CatenaryDropper& d : c.droppers) {
    const DropperProperties p = dropper_properties(m, d);
    all_tension_only = all_tension_only && p.tension_only;
    any_tension_only = any_tension_only || p.tension_only;
    dropper_mass.push_back(p.mass_per_length);
    dropper_damping.push_back(p.damping);
    if (d.stiffness > 0.0)
      stiffness.push_back(d.stiffness);  // the design's EA/l0
    else
      EA.push_back(p.EA);
    if (p.EI > 0.0) EI.push_back(p.EI);
    lower_clamps.push_back(point_mass_at(m, d.contact_node));
    upper_clamps.push_back(point_mass_at(m, d.upper_node));
    design_sags.push_back(-d.design_z);
  }
  const bool cables = !EI.empty();
  const std::string behaviour =
      all_tension_only
          ? (cables ? "tension-only per element on its mean strain (slack in compression, "
                      "smoothed; residue 1e-6 EA)"
                    : "tension-only (slack in compression, sharp switch)")
      : any_tension_only ? "partly tension-only"
                         : "carrying compression too (tension_only: false)";
  const std::string kind =
      cables
          ? cat(plural(static_cast<long long>(c.droppers.size()), "cable"), " of ",
                plural(static_cast<long long>(c.droppers.front().elements.size()), "element"),
                " (ANCF, EI ", range_text(EI, "N*m^2"), ", distributed mass, hinged to the wires)")
          : cat(plural(static_cast<long long>(c.droppers.size()), "bar"), " (axial force only)");
  t.row("droppers",
        cat(kind, ", ", behaviour, ", ",
            stiffness.empty() ? cat("EA ", range_text(EA, "N"))
                              : cat("stiffness ", range_text(stiffness, "N/m")),
            ", ", range_text(dropper_mass, "kg/m"), ", damping ",
            range_text(dropper_damping, "N*s/m"), "; unstretched lengths set by shape finding"),
        4);
  t.row("design sags",
        cat(range_text(design_sags, "m"),
            " below the registrations at the droppers (the contact wire's design shape)"),
        4);
  const double max_clamp = std::max(*std::max_element(lower_clamps.begin(), lower_clamps.end()),
                                    *std::max_element(upper_clamps.begin(), upper_clamps.end()));
  t.row("clamp masses",
        max_clamp > 0.0 ? cat(range_text(lower_clamps, "kg"), " on the contact wire, ",
                              range_text(upper_clamps, "kg"), " on the upper wire, per dropper")
                        : std::string("none (clamp_mass 0)"),
        4);

  double arm_mass = 1.0;  // no steady arms: nothing to leave out
  if (!c.registrations.empty()) {
    std::vector<double> k, damping, mass;
    int held = 0;
    for (const CatenaryRegistration& r : c.registrations) {
      const auto [ks, cs] = vertical_support(m, r.node);
      k.push_back(ks);
      damping.push_back(cs);
      mass.push_back(point_mass_at(m, r.node));
      if (r.load >= 0) ++held;
    }
    t.row("steady arms",
          cat(std::to_string(c.registrations.size()), " vertical springs ", range_text(k, "N/m"),
              ", damping ", range_text(damping, "N*s/m"), ", mass ", range_text(mass, "kg"),
              ", y held; ",
              held > 0 ? cat(std::to_string(held), " preloaded to the design height")
                       : std::string("no preload (hold_design_height false)")),
          4);
    const Messenger ms = messenger_supports(m, c);
    t.row("messenger supp.",
          ms.n_fixed > 0 ? cat(std::to_string(ms.n_fixed), " fixed in z, y held")
                         : cat(std::to_string(ms.stiffness.size()), " vertical springs ",
                               range_text(ms.stiffness, "N/m"), ", damping ",
                               range_text(ms.damping, "N*s/m"), ", y held"),
          4);
    arm_mass = *std::max_element(mass.begin(), mass.end());
  }
  if (c.absorbing_ends)
    t.row("ends",
          "absorbing: both wires pinned at the first and last support for shape finding and the "
          "static start, then cut ends of a longer line (an absorbing end each: waves leave)",
          4);
  else
    t.row("anchors", "both wires pinned (x, y, z) at the first and last support", 4);

  if (c.stitch_wires.empty() && !c.registrations.empty())
    notes.left_out.push_back("stitch wires (catenary.stitch not given)");
  if (c.window)
    notes.left_out.push_back(
        "the line outside the window: waves that leave it never come back, the spans "
        "entering ahead start at rest (the waves that ran ahead of the window are lost), the "
        "line's anchors, sections and other trains beyond the window are not modelled");
  if (c.absorbing_ends)
    notes.left_out.push_back(
        "the line beyond the cut ends: waves that leave never come back (its supports, "
        "droppers and other trains do not reflect them), and the absorbing ends match the "
        "wires' bending only approximately (short waves)");
  else
    notes.left_out.push_back(
        "anchor spans and balance weights: the wire ends are pinned, their tensions set "
        "through the prestrain");
  notes.left_out.push_back(
      "steady-arm rotation: a steady arm is a vertical spring (with a point mass) on the "
      "contact wire");
  if (!cables)
    notes.left_out.push_back(
        "dropper bending and distributed mass: droppers are bars (axial force only, mass "
        "lumped at the ends; droppers.model: cable models both)");
  if (c.dimension == 2)
    notes.left_out.push_back(
        "out-of-plane (y) motion: dimension 2 fixes every wire node's y and slope y");
  if (!any_tension_only)
    notes.left_out.push_back("dropper slackening (droppers.tension_only false)");
  if (*std::max_element(dropper_mass.begin(), dropper_mass.end()) <= 0.0)
    notes.left_out.push_back("dropper mass (droppers.mass_per_length 0)");
  if (max_clamp <= 0.0) notes.left_out.push_back("clamp masses (droppers.clamp_mass 0)");
  if (arm_mass <= 0.0) notes.left_out.push_back("steady-arm mass (steady_arms.mass 0)");
}

}  // namespace catena::model::detail
