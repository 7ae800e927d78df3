#include "catenary_reader.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "catenary_builder.hpp"
#include "catenary_window_reader.hpp"
#include "did_you_mean.hpp"
#include "memory_check.hpp"
#include "physical_bounds.hpp"
#include "rayleigh_reader.hpp"
#include "run_reach.hpp"

namespace catena::model::detail {
namespace {

constexpr std::int64_t max_spans = 10'000;
constexpr double max_catenary_elements = 10'000'000.0;  // per wire, as for lines
constexpr std::int64_t kDefaultRunOutSpans = 2;

const std::vector<std::string>& catenary_keys() {
  static const std::vector<std::string> keys{"dimension",
                                             "spans",
                                             "span_length",
                                             "span_lengths",
                                             "system_height",
                                             "presag",
                                             "presag_between",
                                             "stagger",
                                             "element_length",
                                             "contact_wire",
                                             "messenger",
                                             "droppers",
                                             "steady_arms",
                                             "messenger_supports",
                                             "evaluation_spans",
                                             "run_out_spans",
                                             "stitch",
                                             "acceptance",
                                             "ends",
                                             "window"};
  return keys;
}

const std::vector<std::string>& wire_keys() {
  static const std::vector<std::string> keys{"EA",      "EI",           "mass_per_length",
                                             "tension", "damping_time", "rayleigh"};
  return keys;
}

// A wire's section, tension and damping from a map already checked for its keys.
WireDesign read_wire_values(const Field& wire) {
  WireDesign w;
  w.EA = wire.child("EA").real(RealRange::positive("N"));
  w.EI = wire.child("EI").real(RealRange::positive("N*m^2"));
  w.mass_per_length = wire.child("mass_per_length").real(RealRange::positive("kg/m"));
  // The wire hangs from its tension: none, and the catenary has no shape.
  w.tension = wire.child("tension").real(RealRange::positive("N"));
  w.damping_time = wire.child("damping_time").real_or(0.0, RealRange::non_negative("s"));
  w.rayleigh = read_rayleigh(wire.child("rayleigh"));
  return w;
}

WireDesign read_wire(const Field& wire, const char* what) {
  wire.expect_map(what);
  wire.check_keys(wire_keys());
  return read_wire_values(wire);
}

// The longest stitch accepted (exclusive): each clamp, length/2 from its support, must lie
// inside the adjacent span, and the two stitch wires of a span between two intermediate
// supports must not meet.
double longest_stitch(const std::vector<double>& spans) {
  double longest = std::min(2.0 * spans.front(), 2.0 * spans.back());
  for (std::size_t span = 1; span + 1 < spans.size(); ++span)
    longest = std::min(longest, spans[span]);
  return longest;
}

StitchDesign read_stitch(const Field& stitch, const std::vector<double>& spans) {
  stitch.expect_map(
      "the stitch wires {length, EA, EI, mass_per_length, tension} (one at every "
      "intermediate support)");
  std::vector<std::string> keys = wire_keys();
  keys.emplace_back("length");
  stitch.check_keys(keys);
  if (spans.size() < 2)
    stitch.fail(
        "stitch wires hang at the intermediate supports, and a single span has none; "
        "remove the key or give two spans or more");
  StitchDesign s;
  const Field length = stitch.child("length");
  s.length = length.real(RealRange::positive("m"));
  const double longest = longest_stitch(spans);
  if (!(s.length < longest))
    length.fail("a stitch wire of " + format_number(s.length) + " m does not fit: expected < " +
                format_number(longest) +
                " m, so that each clamp (length/2 from its support) lies inside the adjacent "
                "span and the stitch wires at the two ends of a span do not meet");
  s.wire = read_wire_values(stitch);
  return s;
}

// `spans: auto`: the spans up to the one holding the farthest point a pantograph reaches,
// plus `run_out_spans` more (default 2), so that the far anchor and the reflections from it
// stay away from the last contact point.
std::vector<double> auto_span_lengths(const Field& c, const Field& scene,
                                      std::optional<AutoSpanCount>& why) {
  const Field spans = c.child("spans");
  const Field span_length = c.child("span_length");
  if (c.child("span_lengths").present())
    c.child("span_lengths")
        .fail("give either 'span_lengths' (a list) or 'spans: auto' with 'span_length', not both");
  if (!span_length.present())
    spans.fail("'auto' needs 'span_length' (m): the run's reach is cut into spans of that length");
  const double length = span_length.real(RealRange::positive("m"));
  const RunReach reach = read_run_reach(scene, spans);
  AutoSpanCount count;
  count.reach = reach.farthest;
  count.pantograph = reach.pantograph;
  count.duration = reach.duration;
  count.run_out_spans = static_cast<int>(
      c.child("run_out_spans").integer_or(kDefaultRunOutSpans, IntRange::between(0, max_spans)));
  // The span that holds the reach (a reach exactly on a support ends the span before it).
  const double reached = std::ceil(reach.farthest / length - 1e-9);
  const double n = std::max(1.0, reached) + count.run_out_spans;
  if (n > static_cast<double>(max_spans))
    spans.fail("'auto' gives " + format_number(n) + " spans (pantograph '" + reach.pantograph +
               "' reaches " + format_number(reach.farthest) + " m in " +
               format_number(reach.duration) + " s); at most " + std::to_string(max_spans) +
               " are accepted");
  why = count;
  return std::vector<double>(static_cast<std::size_t>(n), length);
}

std::vector<double> read_span_lengths(const Field& c, const Field& scene,
                                      std::optional<AutoSpanCount>& why) {
  const Field spans = c.child("spans");
  const Field run_out = c.child("run_out_spans");
  const bool automatic = spans.present() && spans.is_scalar() && spans.text() == "auto";
  if (run_out.present() && !automatic)
    run_out.fail(
        "'run_out_spans' goes with 'spans: auto' (the spans added after the run's "
        "reach); with a span count or 'span_lengths' remove it");
  if (automatic) return auto_span_lengths(c, scene, why);
  const Field span_length = c.child("span_length");
  const Field span_lengths = c.child("span_lengths");
  if (span_lengths.present()) {
    if (spans.present() || span_length.present())
      span_lengths.fail(
          "give either 'span_lengths' (a list) or 'spans' with 'span_length', "
          "not both");
    const std::vector<Field> items = span_lengths.items();
    if (items.empty() || items.size() > static_cast<std::size_t>(max_spans))
      span_lengths.fail("expected a list of 1 to " + std::to_string(max_spans) +
                        " span lengths, got " + std::to_string(items.size()));
    std::vector<double> lengths;
    for (const Field& item : items) lengths.push_back(item.real(RealRange::positive("m")));
    return lengths;
  }
  if (!spans.present() && !span_length.present())
    c.fail(
        "missing the spans: give 'spans' (a count) and 'span_length' (m), or "
        "'span_lengths' (a list, m)");
  if (spans.is_scalar() && !parse_integer(spans.text()))
    spans.fail("expected a span count (an integer in [1, " + std::to_string(max_spans) +
               "]) or 'auto' (as many spans as the run reaches, plus run-out spans), got " +
               spans.value_text());
  const std::int64_t n = spans.integer(IntRange::between(1, max_spans));
  const double length = span_length.real(RealRange::positive("m"));
  return std::vector<double>(static_cast<std::size_t>(n), length);
}

// One span's dropper positions: increasing, strictly inside the span.
std::vector<double> read_positions(const Field& list, double span_length, std::size_t span) {
  const std::vector<Field> items = list.items();
  if (items.empty())
    list.fail("span " + std::to_string(span + 1) +
              " has no droppers; expected at least one position in (0, span length)");
  std::vector<double> positions;
  for (const Field& item : items) {
    const double s = item.real(RealRange::between(0.0, false, span_length, false, "m"));
    if (!positions.empty() && !(s > positions.back()))
      item.fail("dropper positions must increase along the span: " + format_number(s) +
                " m follows " + format_number(positions.back()) + " m");
    positions.push_back(s);
  }
  return positions;
}

// A per-span list key (`positions`, `design_sags`): one list for every span, or a list of
// lists (one per span); read_span(list, span) reads span `span`'s list.
template <class ReadSpan>
std::vector<std::vector<double>> read_per_span(const Field& field, std::size_t n_spans,
                                               ReadSpan&& read_span) {
  const std::vector<Field> items = field.items();
  const bool per_span = !items.empty() && items.front().is_list();
  std::vector<std::vector<double>> out;
  if (!per_span) {
    for (std::size_t span = 0; span < n_spans; ++span) out.push_back(read_span(field, span));
    return out;
  }
  if (items.size() != n_spans)
    field.fail("a list per span needs " + std::to_string(n_spans) + " lists (one per span), got " +
               std::to_string(items.size()));
  for (std::size_t span = 0; span < n_spans; ++span) out.push_back(read_span(items[span], span));
  return out;
}

std::vector<std::vector<double>> read_dropper_positions(const Field& positions,
                                                        const std::vector<double>& spans) {
  if (!positions.present())
    positions.fail(
        "missing required key; expected the droppers' distances from the span's "
        "start support (m): a list, or one list per span");
  return read_per_span(positions, spans.size(), [&](const Field& list, std::size_t span) {
    return read_positions(list, spans[span], span);
  });
}

// `droppers.design_sags`: the contact wire's design sag below its registrations at every
// dropper (m, down positive), as many per span as the span has droppers; returned as
// design heights (−sag).
std::vector<std::vector<double>> read_design_sags(const Field& sags,
                                                  const std::vector<std::vector<double>>& positions,
                                                  double system_height) {
  const RealRange range = RealRange::between(-system_height, false, system_height, false, "m");
  return read_per_span(sags, positions.size(), [&](const Field& list, std::size_t span) {
    const std::vector<Field> items = list.items();
    if (items.size() != positions[span].size())
      list.fail("span " + std::to_string(span + 1) + " has " +
                std::to_string(positions[span].size()) + " droppers but " +
                std::to_string(items.size()) +
                " design sags; give one sag (m) per dropper position");
    std::vector<double> heights;
    for (const Field& item : items) heights.push_back(-item.real(range));
    return heights;
  });
}

// The design heights at the droppers: `droppers.design_sags`, or the pre-sag parabola
// (`presag`, zero at the supports or, with `presag_between: end_droppers`, at each span's
// first and last droppers).
std::vector<std::vector<double>> read_design_heights(const Field& catenary,
                                                     const CatenaryDesign& d) {
  const Field presag = catenary.child("presag");
  const Field between = catenary.child("presag_between");
  const Field sags = catenary.child("droppers").child("design_sags");
  if (sags.present()) {
    for (const Field& parabola : {presag, between})
      if (parabola.present())
        parabola.fail(
            "'droppers.design_sags' gives the design heights dropper by dropper; remove "
            "this key (the pre-sag parabola) or the design sags");
    return read_design_sags(sags, d.droppers.positions, d.system_height);
  }
  const double sag =
      presag.real_or(0.0, RealRange::between(0.0, true, d.system_height, false, "m"));
  static const std::vector<std::string> choices{"supports", "end_droppers"};
  const std::string zeros = between.text_or("supports");
  if (std::find(choices.begin(), choices.end(), zeros) == choices.end())
    between.fail("unknown value '" + zeros + "';" + did_you_mean(zeros, choices) +
                 " accepted: supports (the parabola is 0 at the supports), end_droppers (0 "
                 "at each span's first and last droppers)");
  const PresagBetween where =
      zeros == "supports" ? PresagBetween::supports : PresagBetween::end_droppers;
  std::vector<std::vector<double>> heights;
  for (std::size_t span = 0; span < d.span_lengths.size(); ++span) {
    const std::vector<double>& s = d.droppers.positions[span];
    if (where == PresagBetween::end_droppers && s.size() < 2)
      between.fail("span " + std::to_string(span + 1) +
                   " has one dropper: a parabola between its first and last droppers "
                   "needs two; use 'presag_between: supports' or 'droppers.design_sags'");
    heights.push_back(presag_heights(sag, where, s, d.span_lengths[span]));
  }
  return heights;
}

// `clamp_mass`: one mass for both ends of every dropper, or {contact_wire, messenger} (the
// upper end's clamp, on the messenger or on a stitch wire).
void read_clamp_masses(const Field& clamp_mass, DropperDesign& d) {
  const RealRange kg = RealRange::non_negative("kg");
  if (!clamp_mass.is_map()) {
    d.clamp_mass_contact = d.clamp_mass_upper = clamp_mass.real_or(0.0, kg);
    return;
  }
  clamp_mass.check_keys({"contact_wire", "messenger"});
  d.clamp_mass_contact = clamp_mass.child("contact_wire").real(kg);
  d.clamp_mass_upper = clamp_mass.child("messenger").real(kg);
}

// `model: bar` (default) or `cable` with `elements` and `EI`; a cable dropper needs a
// mass: its interior nodes have no other inertia (a massless cable dropper is a bar).
void read_dropper_model(const Field& droppers, DropperDesign& d) {
  const Field model = droppers.child("model");
  const std::string name = model.text_or("bar");
  static const std::vector<std::string> choices{"bar", "cable"};
  if (std::find(choices.begin(), choices.end(), name) == choices.end())
    model.fail("unknown dropper model '" + name + "';" + did_you_mean(name, choices) +
               " accepted: bar (a tension-only bar, mass lumped at its ends), cable (ANCF "
               "cable elements, distributed mass)");
  d.model = name == "cable" ? DropperModel::cable : DropperModel::bar;
  const Field elements = droppers.child("elements");
  const Field EI = droppers.child("EI");
  if (d.model == DropperModel::bar) {
    for (const Field& only_cable : {elements, EI})
      if (only_cable.present())
        only_cable.fail("applies to cable droppers only; add 'model: cable' or remove the key");
    return;
  }
  d.cable_elements = static_cast<int>(elements.integer_or(2, IntRange::between(1, 100)));
  d.EI = EI.real(RealRange::positive("N*m^2"));
  if (!(d.mass_per_length > 0.0))
    droppers.child("mass_per_length")
        .fail(
            "cable droppers need a mass per length > 0 kg/m (the cable's interior nodes "
            "have no other inertia); give the dropper wire's mass or use 'model: bar'");
}

DropperDesign read_droppers(const Field& droppers, const std::vector<double>& spans) {
  droppers.expect_map("the droppers {positions, EA or stiffness, ...}");
  droppers.check_keys({"positions", "model", "elements", "EI", "EA", "stiffness", "mass_per_length",
                       "damping", "tension_only", "clamp_mass", "design_sags"});
  DropperDesign d;
  d.positions = read_dropper_positions(droppers.child("positions"), spans);
  const Field EA = droppers.child("EA");
  const Field stiffness = droppers.child("stiffness");
  if (EA.present() == stiffness.present())
    droppers.fail(EA.present() ? "both 'EA' and 'stiffness' are given; give one: EA (N) or the "
                                 "dropper stiffness EA/length (N/m)"
                               : "missing the dropper's axial stiffness: give 'EA' (N) or "
                                 "'stiffness' (N/m, = EA/length)");
  if (EA.present())
    d.EA = EA.real(RealRange::positive("N"));
  else
    d.stiffness = stiffness.real(RealRange::positive("N/m"));
  d.mass_per_length =
      droppers.child("mass_per_length").real_or(0.0, RealRange::non_negative("kg/m"));
  d.damping = droppers.child("damping").real_or(0.0, RealRange::non_negative("N*s/m"));
  d.tension_only = droppers.child("tension_only").boolean_or(true);
  read_clamp_masses(droppers.child("clamp_mass"), d);
  read_dropper_model(droppers, d);
  return d;
}

SteadyArmDesign read_steady_arms(const Field& arms) {
  arms.expect_map("the steady arms {stiffness, damping, mass, hold_design_height}");
  arms.check_keys({"stiffness", "damping", "mass", "hold_design_height"});
  SteadyArmDesign a;
  a.stiffness = arms.child("stiffness").real(RealRange::non_negative("N/m"));
  a.damping = arms.child("damping").real_or(0.0, RealRange::non_negative("N*s/m"));
  a.mass = arms.child("mass").real_or(0.0, RealRange::non_negative("kg"));
  a.hold_design_height = arms.child("hold_design_height").boolean_or(true);
  return a;
}

MessengerSupportDesign read_messenger_supports(const Field& supports) {
  supports.expect_map("the messenger supports {stiffness, damping} or {fixed: true}");
  supports.check_keys({"fixed", "stiffness", "damping"});
  MessengerSupportDesign s;
  s.fixed = supports.child("fixed").boolean_or(false);
  const Field stiffness = supports.child("stiffness");
  const Field damping = supports.child("damping");
  if (s.fixed) {
    if (stiffness.present() || damping.present())
      (stiffness.present() ? stiffness : damping)
          .fail(
              "a fixed messenger support has no stiffness or damping; give 'fixed: true' "
              "or 'stiffness' (N/m)");
    return s;
  }
  if (!stiffness.present())
    supports.fail(
        "missing the messenger supports' vertical stiffness: give 'stiffness' "
        "(N/m) or 'fixed: true'");
  s.stiffness = stiffness.real(RealRange::positive("N/m"));
  s.damping = damping.real_or(0.0, RealRange::non_negative("N*s/m"));
  return s;
}

std::pair<int, int> read_evaluation_spans(const Field& field, int n_spans) {
  const std::vector<Field> items = field.items();
  if (items.size() != 2)
    field.fail("expected [first, last] (1-based span numbers), got " + field.value_text());
  const IntRange range = IntRange::between(1, n_spans);
  const auto first = static_cast<int>(items[0].integer(range));
  const auto last = static_cast<int>(items[1].integer(range));
  if (last < first)
    items[1].fail("the last evaluation span (" + std::to_string(last) +
                  ") comes before the first (" + std::to_string(first) + ")");
  return {first, last};
}

}  // namespace

void read_catenary(const Field& catenary, const Field& scene, SceneBuild& build,
                   const MemoryBudget& budget) {
  if (!catenary.present()) return;
  catenary.expect_map("a catenary (a map of design data, see docs/scene.md)");
  catenary.check_keys(catenary_keys());

  const Vec3 g = build.model.gravity;
  if (!(g.z() < 0.0 && g.x() == 0.0 && g.y() == 0.0))
    catenary.fail(
        "the catenary is built with z up, so gravity must point along -z; got "
        "gravity " +
        format_vector(g) + " m/s^2");

  CatenaryDesign d;
  d.dimension =
      static_cast<int>(catenary.child("dimension").integer_or(3, IntRange::between(2, 3)));
  if (const Field ends = catenary.child("ends"); ends.present()) {
    static const std::vector<std::string> accepted{"anchored", "absorbing"};
    const std::string text = ends.text();
    if (text != "anchored" && text != "absorbing")
      ends.fail("unknown ends '" + text + "';" + did_you_mean(text, accepted) +
                " expected anchored (the wires held at the first and last supports) or "
                "absorbing (cut ends of a longer line: absorbing ends in a dynamic run)");
    d.absorbing_ends = text == "absorbing";
  }
  d.span_lengths = read_span_lengths(catenary, scene, d.auto_spans);
  const Field height = catenary.child("system_height");
  d.system_height = height.real(RealRange::positive("m"));
  const Field stagger = catenary.child("stagger");
  if (stagger.present() && d.dimension == 2)
    stagger.fail(
        "stagger is a lateral (y) offset; a 2D catenary (dimension: 2) lies in the "
        "x-z plane and has none. Remove the key or use dimension: 3");
  d.stagger = stagger.real_or(0.0, RealRange::any("m"));
  const Field element_length = catenary.child("element_length");
  d.element_length = element_length.real(RealRange::positive("m"));
  double total_length = 0.0;
  for (const double l : d.span_lengths) total_length += l;
  // Each span is within the coordinate bound; their sum must be too (node x coordinates).
  if (total_length > kMaxCoordinate)
    catenary.fail("the spans add up to " + format_number(total_length) + " m; at most " +
                  format_number(kMaxCoordinate) +
                  " m is accepted (node coordinates are bounded, docs/scene.md \"Physical "
                  "bounds\"): fewer or shorter spans");
  if (total_length / d.element_length > max_catenary_elements)
    element_length.fail("element_length " + format_number(d.element_length) + " m gives about " +
                        format_number(total_length / d.element_length) +
                        " elements per wire; at most 1e7 are accepted");

  d.contact_wire = read_wire(catenary.child("contact_wire"),
                             "the contact wire {EA, EI, mass_per_length, tension}");
  d.messenger = read_wire(catenary.child("messenger"),
                          "the messenger wire {EA, EI, mass_per_length, tension}");
  d.droppers = read_droppers(catenary.child("droppers"), d.span_lengths);
  d.droppers.design_z = read_design_heights(catenary, d);
  // Intermediate supports exist only with two spans or more.
  const bool has_intermediate_supports = d.span_lengths.size() > 1;
  const Field arms = catenary.child("steady_arms");
  const Field messenger_supports = catenary.child("messenger_supports");
  if (has_intermediate_supports || arms.present()) d.steady_arms = read_steady_arms(arms);
  if (has_intermediate_supports || messenger_supports.present())
    d.messenger_supports = read_messenger_supports(messenger_supports);
  if (const Field stitch = catenary.child("stitch"); stitch.present())
    d.stitch = read_stitch(stitch, d.span_lengths);
  if (const Field spans = catenary.child("evaluation_spans"); spans.present())
    d.evaluation_spans = read_evaluation_spans(spans, static_cast<int>(d.span_lengths.size()));
  if (const Field acceptance = catenary.child("acceptance"); acceptance.present()) {
    if (acceptance.text() != "en50318")
      acceptance.fail("unknown acceptance ranges '" + acceptance.text() +
                      "'; accepted: en50318 (the EN 50318 reference case's ranges at 250 and "
                      "300 km/h, checked by `catena stats`)");
    if (!d.evaluation_spans)
      acceptance.fail(
          "the acceptance ranges hold over an evaluation section: give evaluation_spans "
          "(EN 50318: the middle two spans of ten, [5, 6])");
    build.model.acceptance = acceptance.text();
  }

  const std::optional<CatenaryWindow> window = read_catenary_window(catenary, scene, d);
  const std::optional<std::pair<int, int>> evaluation_spans = d.evaluation_spans;
  if (window) cut_design_to_window(*window, d);
  check_catenary_fits(element_length, d, build, budget);
  build_catenary(d, catenary, build);
  if (window) place_window(*window, evaluation_spans, build.model);
}

}  // namespace catena::model::detail
