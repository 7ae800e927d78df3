// The moving part of the `catena check` summary: moving loads and pantographs (path,
// speed, forces, stages, contact), when each is on its path within the analysis, what the
// pantograph model leaves out, and warnings when a load or pantograph leaves its path
// before the analysis ends or does not cross the evaluation section in time.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "catena/model/contact_mode.hpp"
#include "catena/model/path_stations.hpp"
#include "number_format.hpp"
#include "summary_table.hpp"

namespace catena::model::detail {
namespace {

// The sets (line names) of a path's elements, in path order, each once: "cw1, cw2".
std::string path_sets(const Model& m, const std::vector<int>& elements) {
  std::vector<std::string> names;
  for (const int e : elements) {
    const std::string& set = m.elements[static_cast<std::size_t>(e)].set;
    if (names.empty() || names.back() != set) names.push_back(set);
  }
  std::string text;
  for (const std::string& n : names) text += cat(text.empty() ? "" : ", ", n);
  return text;
}

std::string speed_text(double speed) {
  return cat(format_number(std::abs(speed)), " m/s (", format_number(std::abs(speed) * 3.6),
             " km/h)", speed < 0.0 ? " backward (toward decreasing arc length)" : "");
}

// Where something moving at `speed` from `start` (m along a path of length `length`, at
// time t0) is on the path within [t0, t_end]: the time interval, empty if never.
struct OnPath {
  bool ever = false;
  double t_enter = 0.0, t_leave = 0.0;  // s
};
OnPath on_path(double start, double speed, double t0, double t_end, double length) {
  OnPath o;
  if (speed == 0.0) {
    o.ever = start >= 0.0 && start <= length;
    o.t_enter = t0;
    o.t_leave = t_end;
    return o;
  }
  // Forward it enters at arc length 0 and leaves at the end; backward the other way round.
  const double enter_at = speed > 0.0 ? 0.0 : length, leave_at = speed > 0.0 ? length : 0.0;
  o.t_enter = std::max(t0, t0 + (enter_at - start) / speed);
  o.t_leave = std::min(t_end, t0 + (leave_at - start) / speed);
  o.ever = o.t_enter <= o.t_leave;
  return o;
}

std::string on_path_text(const OnPath& o, double start, double speed, double t0) {
  if (!o.ever) return "never on its path within the analysis";
  const auto s = [&](double t) { return start + speed * (t - t0); };
  return cat("on the path from t = ", format_number(o.t_enter), " s to ", format_number(o.t_leave),
             " s (", format_number(s(o.t_enter)), " m to ", format_number(s(o.t_leave)), " m)");
}

// Warning when a load or pantograph runs off the end of its path before the analysis ends.
void warn_path_end(const std::string& what, double start, double speed, double t0, double t_end,
                   double length, SummaryNotes& notes) {
  if (speed == 0.0 || (speed > 0.0 && start > length) || (speed < 0.0 && start < 0.0)) return;
  const double t_leave = t0 + ((speed > 0.0 ? length : 0.0) - start) / speed;
  if (t_leave >= t_end) return;
  notes.warnings.push_back(cat(what, " runs beyond the ", speed > 0.0 ? "end" : "start",
                               " of its path (", format_number(speed > 0.0 ? length : 0.0),
                               " m) at t = ", format_number(t_leave),
                               " s, before the analysis ends at ", format_number(t_end),
                               " s: it acts on nothing from then on"));
}

// Warning when a pantograph on the evaluation section's path does not cover
// [evaluation_start, evaluation_end] within the analysis; `start` is its start on the line
// (the window's path start is not the line's).
void warn_evaluation(const Model& m, const MovingContact& c, double start, double t_end,
                     SummaryNotes& notes) {
  const double a = m.evaluation_start, b = m.evaluation_end;
  const double s0 = start, s1 = start + c.speed * t_end;
  if (std::min(s0, s1) <= a && std::max(s0, s1) >= b) return;
  std::string text =
      cat("pantograph '", c.name, "' does not traverse the evaluation section (", format_number(a),
          " m to ", format_number(b), " m) within the analysis: it covers ", format_number(s0),
          " m to ", format_number(s1), " m in ", format_number(t_end), " s");
  // Forward it enters the section at a and leaves at b; backward at b and a.
  const double entry = c.speed >= 0.0 ? a : b, exit = c.speed >= 0.0 ? b : a;
  const double ahead = c.speed >= 0.0 ? 1.0 : -1.0;  // along the direction of travel
  if ((s0 - entry) * ahead > 0.0)
    text += cat("; it starts ", format_number(std::abs(s0 - entry)), " m inside or beyond it");
  if ((exit - s1) * ahead > 0.0 && c.speed != 0.0)
    text += cat("; reaching ", format_number(exit),
                " m needs analysis.duration >= ", format_number((exit - s0) / c.speed), " s");
  notes.warnings.push_back(text);
}

void describe_moving_loads(const Model& m, double t_end, SummaryTable& t, SummaryNotes& notes) {
  t.row("moving loads", std::to_string(m.moving_loads.size()));
  for (const MovingLoad& load : m.moving_loads) {
    const double length = path_stations(m, load.elements).length();
    t.row(load.name,
          cat("lines ", path_sets(m, load.elements), " (", format_number(length), " m), force ",
              format_vector(load.force), " N, ", speed_text(load.speed), ", at ",
              format_number(load.start), " m at t = ", format_number(load.start_time), " s"),
          4);
    const OnPath o = on_path(load.start, load.speed, load.start_time, t_end, length);
    t.row("", on_path_text(o, load.start, load.speed, load.start_time), 4);
    warn_path_end(cat("moving load '", load.name, "'"), load.start, load.speed, load.start_time,
                  t_end, length, notes);
  }
}

std::string stages_text(const MovingContact& c) {
  std::string text;
  for (std::size_t i = 0; i < c.stages.size(); ++i) {
    const MovingContact::Stage& s = c.stages[i];
    const bool last = i + 1 == c.stages.size();
    text += cat(i == 0 ? "" : "; ", format_number(s.mass), " kg, ", format_number(s.stiffness),
                last ? " N/m and " : " N/m, ", format_number(s.damping),
                last ? " N*s/m to ground" : " N*s/m");
  }
  return text;
}

// A multistep method's fixed step against the contact spring's own mode
// (model/contact_mode.hpp): beyond its limit the method's numerical damping gives a smooth
// but wrong contact force, which no later check of the force itself can see, so it is said
// before the run.
void warn_multistep_contact(const Model& m, const MovingContact& c, SummaryNotes& notes) {
  const double limit = multistep_contact_limit(m);
  const IntegratorOptions& integrator = m.dynamic_options.integrator;
  const double omega = contact_mode(m, c).omega;
  const double dt_omega = omega * integrator.dt;
  if (!(dt_omega > limit)) return;
  notes.warnings.push_back(
      cat("pantograph '", c.name, "': integrator '", integrator.type, "' at dt ",
          format_number(integrator.dt), " s gives the contact spring's own mode (",
          format_number(omega), " rad/s: contact.stiffness ", format_number(c.stiffness),
          " N/m between the head and the wire) ",
          format_number(std::round(2.0 * std::numbers::pi / dt_omega)),
          " steps a period (dt*omega = ", format_number(dt_omega), " > ", format_number(limit),
          "): a multistep method's numerical damping smooths it into a contact force that is "
          "wrong without looking rough (sigma measured 1-2 % off on EN 50318's contact at "
          "dt*omega 0.28-0.39), which the run's resolution check cannot see; integrator.dt <= ",
          format_number(limit / omega),
          " s gives it the steps it needs, or use hht or radau (docs/accuracy.md, \"The "
          "multistep methods' gap\": a contact that loses contact and strikes again needs "
          "more)"));
}

}  // namespace

void describe_moving(const Model& m, SummaryTable& t, SummaryNotes& notes) {
  const bool dynamic = m.analysis == AnalysisType::dynamic;
  const double t_end = dynamic ? m.dynamic_options.duration : 0.0;
  if (!m.moving_loads.empty()) describe_moving_loads(m, t_end, t, notes);
  if (m.contacts.empty()) return;
  // How many pantographs have a property, and that share in words (none, all or some).
  const auto count = [&m](bool MovingContact::*property) {
    return static_cast<std::size_t>(std::count_if(
        m.contacts.begin(), m.contacts.end(), [&](const MovingContact& c) { return c.*property; }));
  };
  const auto share = [&m](std::size_t n, const char* none, const char* all, const char* some) {
    return n == 0 ? none : n == m.contacts.size() ? all : some;
  };
  const char* contact = share(count(&MovingContact::bilateral), "penalty contact",
                              "bilateral contact", "penalty and bilateral contacts");
  const std::size_t mechanisms = count(&MovingContact::mechanism);
  const char* kind =
      share(mechanisms, "lumped-mass stages moving vertically",
            "single-arm mechanisms of rigid bodies", "lumped stages and single-arm mechanisms");
  t.row("pantographs", cat(std::to_string(m.contacts.size()), " (", kind, ", ", contact, ")"));
  for (std::size_t i = 0; i < m.contacts.size(); ++i) {
    const MovingContact& c = m.contacts[i];
    const ElementPath& path = m.paths[static_cast<std::size_t>(c.path)];
    // With a window, where it is on the line (the window is a few spans of it).
    const std::optional<CatenaryWindow>& window =
        m.catenary ? m.catenary->window : std::optional<CatenaryWindow>();
    const double length =
        window ? window->line_spans * window->span_arc : path_stations(m, path.elements).length();
    const double start = c.start + (window ? window->origin_arc() : 0.0);
    const double uplift = c.static_force + c.aerodynamic_coefficient * c.speed * c.speed;
    // A path the reader made from `line:` is named after the pantograph: show its lines.
    const std::string path_text = path.name == cat("pantograph ", c.name)
                                      ? cat("lines ", path_sets(m, path.elements))
                                      : cat("path ", path.name);
    t.row(c.name,
          cat(path_text, " (", format_number(length), window ? " m of line), " : " m), ",
              speed_text(c.speed), ", start ", format_number(start), " m"),
          4);
    if (c.mechanism) {
      t.row("",
            cat("arm_en50318: an arm on a revolute joint at ", format_number(c.arm_angle),
                " degrees, the head on a prismatic suspension; bodies '", c.name, " arm' and '",
                c.name, " head'"),
            4);
      t.row("", cat("equivalent stages there (head first): ", stages_text(c)), 4);
    } else {
      t.row("", cat("stages (head first): ", stages_text(c)), 4);
    }
    t.row("",
          cat("static force ", format_number(c.static_force), " N, aerodynamic coefficient ",
              format_number(c.aerodynamic_coefficient), " N*s^2/m^2: uplift ",
              format_number(uplift), " N"),
          4);
    t.row("",
          c.bilateral ? std::string("contact bilateral: a multiplier holds the head on the "
                                    "wire (its force may turn negative)")
                      : cat("contact stiffness ", format_number(c.stiffness), " N/m, damping ",
                            format_number(c.damping), " N*s/m"),
          4);
    if (!dynamic) {
      t.row("", cat("standing at ", format_number(start), " m (static analysis)"), 4);
      continue;
    }
    const OnPath o = on_path(start, c.speed, 0.0, t_end, length);
    t.row("", on_path_text(o, start, c.speed, 0.0), 4);
    const std::string who = cat("pantograph '", c.name, "'");
    if (!o.ever)
      notes.warnings.push_back(cat(who, " is never on its path (", format_number(length),
                                   " m) within the analysis (0 to ", format_number(t_end),
                                   " s): it touches nothing"));
    else
      warn_path_end(who, start, c.speed, 0.0, t_end, length, notes);
    // Off its path at the start: no static contact, and the statistics' start-up with it.
    if (o.ever && o.t_enter > 0.0)
      notes.warnings.push_back(cat(who, " starts off its path (at ", format_number(start),
                                   " m; the path runs from 0 to ", format_number(length),
                                   " m) and touches nothing until t = ", format_number(o.t_enter),
                                   " s"));
    if (m.evaluation_end > m.evaluation_start && c.path == m.contacts.front().path)
      warn_evaluation(m, c, start, t_end, notes);
    warn_multistep_contact(m, c, notes);
    if (c.aerodynamic_coefficient == 0.0)
      notes.left_out.push_back(cat(who, ": aerodynamic uplift (aerodynamic_coefficient 0)"));
    if (c.damping == 0.0 && !c.bilateral)
      notes.left_out.push_back(cat(who, ": contact damping (contact.damping 0)"));
  }
  if (mechanisms < m.contacts.size())
    notes.left_out.push_back(
        "pantograph stages' weight (cancelled: the static force is the net uplift), their "
        "horizontal motion and the head's rotation");
  if (mechanisms > 0)
    notes.left_out.push_back(
        "arm_en50318 pantographs: the head's motion along the wire relative to the contact "
        "point (the contact acts at the head's point, at the wire's moving contact point)");
}

bool structure_is_damped(const Model& m) {
  std::vector<bool> pantograph_node(m.nodes.size(), false);
  for (const MovingContact& c : m.contacts)
    for (const int node : pantograph_nodes(c))
      pantograph_node[static_cast<std::size_t>(node)] = true;
  for (const ElementDesc& e : m.elements) {
    if (pantograph_node[static_cast<std::size_t>(e.nodes.front())]) continue;
    if (const auto* cable = std::get_if<CableProps>(&*e.props);
        cable && (cable->damping_time > 0.0 || cable->rayleigh.active()))
      return true;
    if (const auto* beam = std::get_if<BeamProps>(&*e.props);
        beam && (beam->damping_time > 0.0 || beam->rayleigh.active()))
      return true;
    if (const auto* bar = std::get_if<BarProps>(&*e.props); bar && bar->damping > 0.0) return true;
    if (const auto* spring = std::get_if<SpringProps>(&*e.props);
        spring && spring->damping.maxCoeff() > 0.0)
      return true;
  }
  for (const ElasticSupport& s : m.elastic_supports)
    if (!pantograph_node[static_cast<std::size_t>(s.node)] && s.damping.maxCoeff() > 0.0)
      return true;
  return false;
}

}  // namespace catena::model::detail
