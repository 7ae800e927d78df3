#include "catenary_window_reader.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "catena/core/error.hpp"
#include "catena/model/integrator_catalogue.hpp"
#include "catena/model/path_stations.hpp"
#include "number_format.hpp"
#include "speed_reader.hpp"

namespace catena::model::detail {
namespace {

constexpr std::int64_t kMaxWindowSpans = 1000;
constexpr std::int64_t kDefaultBehind = 2;

// The scene's first pantograph on the contact wire: its start (m along the line) and its
// velocity (m/s along the path).
struct FirstPantograph {
  double start = 0.0, velocity = 0.0;
  std::string name;
  Field entry;
};

FirstPantograph first_pantograph(const Field& scene, const Field& window) {
  for (const Field& entry : scene.child("pantographs").items()) {
    if (!entry.is_map() || entry.child("path").text_or("") != kContactWirePath) continue;
    return {entry.child("start").real_or(0.0, RealRange::any("m")), read_path_velocity(entry),
            entry.child("name").text_or(""), entry};
  }
  window.fail(
      "a window follows the pantographs along the line, but no pantograph runs on the "
      "contact wire (pantographs: [{path: contact_wire, ...}]); remove the key to model the "
      "whole line");
}

// m of contact wire per span: straight from support to support, from one side of the
// stagger to the other.
double wire_per_span(const CatenaryDesign& d, double span_length) {
  return d.dimension == 3 ? std::hypot(span_length, 2.0 * d.stagger) : span_length;
}

void require_repeating_line(const Field& window, const CatenaryDesign& d) {
  for (std::size_t span = 1; span < d.span_lengths.size(); ++span)
    if (d.span_lengths[span] != d.span_lengths[0])
      window.fail("a window needs a line that repeats span after span, but span " +
                  std::to_string(span + 1) + " is " + format_number(d.span_lengths[span]) +
                  " m long and span 1 " + format_number(d.span_lengths[0]) +
                  " m; give equal spans (spans and span_length) or remove the key");
  for (std::size_t span = 1; span < d.droppers.positions.size(); ++span)
    if (d.droppers.positions[span] != d.droppers.positions[0] ||
        d.droppers.design_z[span] != d.droppers.design_z[0])
      window.fail(
          "a window needs a line that repeats span after span, but the droppers of "
          "span " +
          std::to_string(span + 1) +
          " differ from span 1's (positions or design heights); give one dropper "
          "layout for every span or remove the key");
}

}  // namespace

std::optional<CatenaryWindow> read_catenary_window(const Field& catenary, const Field& scene,
                                                   const CatenaryDesign& d) {
  const Field window = catenary.child("window");
  if (!window.present()) return std::nullopt;
  window.expect_map("a window {spans, behind} (docs/scene.md)");
  window.check_keys({"spans", "behind"});
  if (d.auto_spans)
    catenary.child("spans").fail(
        "'auto' sizes a modelled line to the run's reach; with a window the line's length "
        "costs nothing: give the span count of the line (an integer)");
  if (const Field ends = catenary.child("ends"); ends.present() && ends.text() != "absorbing")
    ends.fail(
        "a window's ends are absorbing ends (the line goes on beyond them); remove "
        "'ends: " +
        ends.text() + "' or the window");
  require_repeating_line(window, d);
  // A stitch wire spans a support; the window's first and last supports would have none, so
  // their spans' droppers would hang otherwise than the line's.
  if (d.stitch)
    catenary.child("stitch").fail(
        "stitch wires are not available with a window yet (the window's end supports would "
        "have none, and the spans next to them would not repeat the line's); remove "
        "'stitch' or the window");
  const std::string type = scene.child("analysis").child("type").text_or("static");
  if (type != "dynamic")
    window.fail("a window follows the pantographs in a dynamic run; this scene's analysis is '" +
                type + "' (analysis.type: dynamic, or remove the key)");

  CatenaryWindow w;
  w.line_spans = static_cast<int>(d.span_lengths.size());
  w.span_length = d.span_lengths.front();
  // The line repeats every span, or every two where the wires zigzag (stagger alternates).
  w.period = d.dimension == 3 && d.stagger != 0.0 ? 2 : 1;
  w.spans = static_cast<int>(window.child("spans").integer(IntRange::between(1, kMaxWindowSpans)));
  // A pantograph on a window's end element lifts the end, which has no stiffness of its
  // own (docs/scene.md, absorbing_ends): one whole span behind it at least.
  w.behind = static_cast<int>(
      window.child("behind").integer_or(kDefaultBehind, IntRange::between(1, kMaxWindowSpans)));
  // The pantograph stays in spans [behind, behind + period) and one span at least lies
  // ahead of them.
  const int least = w.behind + w.period + 1;
  if (w.spans < least)
    window.child("spans").fail(
        "a window of " + std::to_string(w.spans) + " spans cannot hold " +
        std::to_string(w.behind) + " behind the pantograph (behind), the " +
        std::to_string(w.period) + " it crosses before the window moves" +
        (w.period > 1 ? std::string(" (the stagger repeats every 2 spans)") : std::string()) +
        " and one ahead: give spans >= " + std::to_string(least));
  if (w.spans >= w.line_spans)
    window.child("spans").fail("a window of " + std::to_string(w.spans) + " spans on a line of " +
                               std::to_string(w.line_spans) +
                               " models no less than the line: remove the key, or describe "
                               "the longer line (spans)");
  const FirstPantograph p = first_pantograph(scene, window);
  if (!(p.velocity > 0.0)) {
    const Field direction = p.entry.child("direction");
    (direction.present() ? direction : p.entry)
        .fail("pantograph '" + p.name +
              "' does not run forward along the line (speed > 0, direction: forward): a "
              "catenary.window moves forward only");
  }
  // The window starts `behind` spans before the pantograph's span, on a multiple of the
  // period so that the stagger's sides are the line's.
  const int span = static_cast<int>(std::floor(p.start / wire_per_span(d, w.span_length)));
  w.origin_span =
      static_cast<int>(std::floor(static_cast<double>(span - w.behind) / w.period)) * w.period;
  return w;
}

void cut_design_to_window(const CatenaryWindow& w, CatenaryDesign& d) {
  const auto spans = static_cast<std::size_t>(w.spans);
  d.span_lengths.assign(spans, w.span_length);
  d.droppers.positions.resize(spans, d.droppers.positions.front());
  d.droppers.design_z.resize(spans, d.droppers.design_z.front());
  d.x_origin = w.origin_span * w.span_length;
  d.evaluation_spans.reset();
  d.absorbing_ends = true;
}

void place_window(CatenaryWindow w, const std::optional<std::pair<int, int>>& evaluation_spans,
                  Model& m) {
  CATENA_ASSERT(m.catenary.has_value(), "a window is placed after its catenary is built");
  const auto path = std::find_if(m.paths.begin(), m.paths.end(),
                                 [](const ElementPath& p) { return p.name == kContactWirePath; });
  CATENA_ASSERT(path != m.paths.end(), "the catenary builder made the contact-wire path");
  w.span_arc = path_stations(m, path->elements).length() / w.spans;
  if (evaluation_spans) {
    m.evaluation_start = (evaluation_spans->first - 1) * w.span_arc;
    m.evaluation_end = evaluation_spans->second * w.span_arc;
  }
  m.catenary->window = w;
}

void place_pantograph_in_window(const Field& entry, const Model& m, MovingContact& c) {
  if (!m.catenary || !m.catenary->window) return;
  const CatenaryWindow& w = *m.catenary->window;
  if (m.paths[static_cast<std::size_t>(c.path)].name != kContactWirePath)
    entry.child("path").fail(
        "in a scene with catenary.window the pantographs run on the "
        "contact wire (path: contact_wire): the window follows them there");
  c.start -= w.origin_arc();
  if (m.contacts.empty()) return;  // the first: the window was placed around it
  const MovingContact& first = m.contacts.front();
  if (c.speed != first.speed)
    entry.fail("pantograph '" + c.name + "' runs at " + format_number(c.speed) +
               " m/s and the first, '" + first.name + "', at " + format_number(first.speed) +
               " m/s: a window follows one speed (give them the same speed, or model the "
               "line without a window)");
  // The first stays in [behind, behind + period) spans; this one keeps its distance to it.
  const double d = c.start - first.start, s = w.span_arc;
  const double low = (1 - w.behind) * s, high = (w.spans - 1 - w.behind - w.period) * s;
  if (d < low || d > high)
    entry.child("start").fail(
        "pantograph '" + c.name + "' is " + format_number(d) + " m from the first, '" + first.name +
        "'; the window (" + std::to_string(w.spans) + " spans, behind " + std::to_string(w.behind) +
        ") keeps a span between each pantograph and its ends only for " + format_number(low) +
        " to " + format_number(high) + " m: give the window more spans (or more behind it)");
}

void check_window_scene(const Field& scene, const Model& m) {
  if (!m.catenary || !m.catenary->window) return;
  const Field window = scene.child("catenary").child("window");
  for (const char* key :
       {"nodes", "elements", "lines", "bodies", "sliders", "supports", "elastic_supports",
        "constraints", "joints", "absorbing_ends", "loads", "masses", "surfaces", "moving_loads"})
    if (const Field f = scene.child(key); f.present())
      f.fail(std::string("a scene with catenary.window holds the catenary and its pantographs "
                         "only: the window moves along the line, and '") +
             key + "' would stay behind; remove it or model the line without a window");
  const Field analysis = scene.child("analysis");
  if (m.dynamic_options.structure == StructureModel::modal)
    analysis.child("structure")
        .fail(
            "structure: modal has no window (modal coordinates belong to one stretch of line); "
            "use structure: linear or nonlinear with catenary.window");
  if (!m.dynamic_options.initial.from_static)
    analysis.child("initial").child("from").fail(
        "a window starts from the line's static state (its ends where the line has them, the "
        "spans entering ahead at rest): remove 'from: reference'");
  const IntegratorType* type = find_integrator_type(m.dynamic_options.integrator.type);
  if (type && type->method != IntegratorMethod::hht && type->method != IntegratorMethod::irk)
    scene.child("integrator")
        .child("type")
        .fail("integrator '" + m.dynamic_options.integrator.type +
              "' cannot follow a window: when the window moves, the state moves back a span, and a "
              "multistep or PETSc method's history would not; use hht or an implicit Runge-Kutta "
              "method (" +
              integrator_names(IntegratorMethod::irk) + ")");
}

}  // namespace catena::model::detail
