#include "pantograph_reader.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "catena/model/integrator_catalogue.hpp"
#include "catenary_window_reader.hpp"
#include "line_path_reader.hpp"
#include "number_format.hpp"
#include "output_name.hpp"
#include "pantograph_mechanism.hpp"
#include "speed_reader.hpp"

namespace catena::model::detail {
namespace {

struct Stage {
  double mass = 0.0, stiffness = 0.0, damping = 0.0;
};

// EN 50318's two-stage reference pantograph as reproduced in published validations
// (EN 50318:2002 as reproduced in published validations; docs/validation.md): head m1 on frame m2.
const std::vector<Stage>& en50318_stages() {
  static const std::vector<Stage> stages{{7.2, 4200.0, 10.0}, {15.0, 50.0, 90.0}};
  return stages;
}
constexpr double kEn50318ContactStiffness = 50000.0;  // N/m

std::vector<Stage> read_stages(const Field& list) {
  std::vector<Stage> stages;
  const std::vector<Field> items = list.items();
  if (items.size() < 1 || items.size() > 5)
    list.fail("expected 1 to 5 stages (head first, the last joined to the ground), got " +
              std::to_string(items.size()));
  for (const Field& item : items) {
    item.expect_map("a stage {mass, stiffness, damping}");
    item.check_keys({"mass", "stiffness", "damping"});
    Stage s;
    s.mass = item.child("mass").real(RealRange::positive("kg"));
    s.stiffness = item.child("stiffness").real(RealRange::non_negative("N/m"));
    s.damping = item.child("damping").real_or(0.0, RealRange::non_negative("N*s/m"));
    stages.push_back(s);
  }
  if (stages.back().stiffness <= 0.0)
    items.back()
        .child("stiffness")
        .fail(
            "the last stage is joined to the ground by this stiffness; it must be > 0, else "
            "the pantograph is a free body");
  return stages;
}

// Reference position of the path at arc length s (linear between the element's end nodes).
Vec3 path_point(const Model& m, const ElementPath& path, double s, double& length) {
  length = 0.0;
  Vec3 at = Vec3::Zero();
  bool found = false;
  for (int e : path.elements) {
    const auto& nodes = m.elements[static_cast<size_t>(e)].nodes;
    const Vec3 a = m.nodes[static_cast<size_t>(nodes.front())].position;
    const Vec3 b = m.nodes[static_cast<size_t>(nodes.back())].position;
    const double L = (b - a).norm();
    if (!found && s <= length + L) {
      at = a + (b - a) * ((s - length) / L);
      found = true;
    }
    length += L;
  }
  return at;
}

// The horizontal direction of travel along the path at s (toward increasing s).
Vec3 travel_direction(const Model& m, const ElementPath& path, double s, double length) {
  double unused = 0.0;
  const double a = std::clamp(s - 0.5, 0.0, length), b = std::clamp(s + 0.5, 0.0, length);
  Vec3 d = path_point(m, path, b, unused) - path_point(m, path, a, unused);
  d.z() = 0.0;
  return d.normalized();
}

// A bilateral contact holds the head on the wire at every step: its contact point must stay
// on the path from start to where the speed takes it by the end, and the modal model (which
// takes contacts as forces) cannot hold it.
void check_bilateral_contact(const Field& type, const Model& m, const MovingContact& c) {
  // A window keeps its pantographs inside it (place_pantograph_in_window).
  const bool window = m.catenary && m.catenary->window;
  double length = 0.0;
  path_point(m, m.paths[static_cast<size_t>(c.path)], 0.0, length);
  const double t_end = m.analysis == AnalysisType::dynamic ? m.dynamic_options.duration : 0.0;
  const double from = c.start, to = c.start + c.speed * t_end;
  if (!window && (std::min(from, to) < 0.0 || std::max(from, to) > length))
    type.fail(
        "a bilateral contact holds the head on the wire for the whole run, so its contact "
        "point must stay on the path: it runs from " +
        format_number(from) + " to " + format_number(to) + " m, the path from 0 to " +
        format_number(length) + " m; move `start` or shorten analysis.duration");
  if (m.analysis == AnalysisType::dynamic && m.dynamic_options.structure == StructureModel::modal)
    type.fail(
        "a bilateral contact is not available with structure: modal (the modal model "
        "takes contacts as forces); use structure: nonlinear or linear");
}

// The lumped stages: the head at the wire's reference point, the other stages below (the
// springs act on displacements, so the spacing is only for pictures).
void add_stages(SceneBuild& build, int origin, const std::vector<Stage>& stages, MovingContact& c,
                const Vec3& contact_point, double uplift, std::int64_t& next_node_id,
                std::int64_t& next_element_id) {
  Model& m = build.model;
  const Vec3 up = c.up;
  std::vector<int> stage_nodes;
  for (size_t i = 0; i < stages.size(); ++i) {
    Node node;
    node.id = next_node_id++;
    node.position = contact_point - up * (0.5 * static_cast<double>(i));
    build.add_node(node, origin);
    stage_nodes.push_back(static_cast<int>(m.nodes.size()) - 1);
    m.supports.push_back({stage_nodes.back(), 0b011u});  // x and y held
    m.point_masses.push_back({stage_nodes.back(), stages[i].mass});
    m.nodal_loads.push_back({stage_nodes.back(), -stages[i].mass * m.gravity});
  }
  for (size_t i = 0; i + 1 < stages.size(); ++i) {
    ElementDesc spring;
    spring.id = next_element_id++;
    spring.nodes = {stage_nodes[i], stage_nodes[i + 1]};
    spring.props = SpringProps{up * stages[i].stiffness, up * stages[i].damping};
    spring.set = "pantograph " + c.name;
    build.add_element(spring, origin);
  }
  m.elastic_supports.push_back(
      {stage_nodes.back(), up * stages.back().stiffness, up * stages.back().damping});
  m.nodal_loads.push_back({stage_nodes.back(), up * uplift});
  c.head_node = stage_nodes.front();
}

// The mechanism's bodies need the nonlinear structure and an integrator that keeps their
// nonlinear constraints (checked before the pantographs were read, without them).
void check_mechanism_analysis(const Field& model_field, const Model& m) {
  if (m.analysis != AnalysisType::dynamic) return;
  if (m.dynamic_options.structure != StructureModel::nonlinear)
    model_field.fail(
        "a pantograph of model arm_en50318 is a mechanism of rigid bodies, which the " +
        std::string(m.dynamic_options.structure == StructureModel::modal ? "modal" : "linear") +
        " structure does not take; use structure: nonlinear, or model: en50318");
  if (const auto refusal =
          refuse_integrator(m.dynamic_options.integrator, m.constraints.size(), true))
    model_field.fail(refusal->why + " (the arm_en50318 pantograph is made of rigid bodies)");
}

}  // namespace

void read_pantographs(const Field& pantographs, SceneBuild& build) {
  if (!pantographs.present()) return;
  Model& m = build.model;
  const double g = m.gravity.norm();
  const Vec3 up = g > 0.0 ? Vec3(-m.gravity / g) : Vec3(Vec3::UnitZ());
  if (std::abs(up.z()) < 1.0 - 1e-12)
    pantographs.fail("pantographs move vertically: gravity must point along -z (it is " +
                     std::to_string(m.gravity.x()) + ", " + std::to_string(m.gravity.y()) + ", " +
                     std::to_string(m.gravity.z()) + ")");
  std::int64_t next_node_id = 0, next_element_id = 0;
  for (const Node& n : m.nodes) next_node_id = std::max(next_node_id, n.id + 1);
  for (const ElementDesc& e : m.elements) next_element_id = std::max(next_element_id, e.id + 1);
  std::set<std::string> names;
  for (const Field& entry : pantographs.items()) {
    entry.expect_map("a pantograph {name, path, speed or speed_kmh, start, static_force, ...}");
    entry.check_keys({"name", "path", "line", "speed", "speed_kmh", "direction", "start",
                      "static_force", "aerodynamic_coefficient", "model", "stages", "contact",
                      "arm_angle"});
    MovingContact c;
    // Required, and a group of the output (/pantographs/<name>).
    c.name = read_output_name(entry.child("name"), entry.child("name").text(), "a pantograph");
    if (!names.insert(c.name).second)
      entry.child("name").fail("pantograph name '" + c.name + "' is used twice");
    c.path = read_path_or_line(entry, build, "pantograph " + c.name, "pantographs");
    c.speed = read_path_velocity(entry);
    double path_length = 0.0;
    path_point(m, m.paths[static_cast<size_t>(c.path)], 0.0, path_length);
    // A start outside [0, path length] is a pantograph that reaches (or has left) the wire
    // later: no contact while it is off the path. Its nodes are drawn at the nearest end.
    c.start = entry.child("start").real_or(0.0, RealRange::any("m"));
    place_pantograph_in_window(entry, m, c);  // the line's start to the window's
    const Vec3 contact_point = path_point(m, m.paths[static_cast<size_t>(c.path)],
                                          std::clamp(c.start, 0.0, path_length), path_length);
    const double static_force = entry.child("static_force").real(RealRange::positive("N"));
    const double aero =
        entry.child("aerodynamic_coefficient").real_or(0.0, RealRange::any("N*s^2/m^2"));

    std::vector<Stage> stages;
    const Field model_field = entry.child("model"), stages_field = entry.child("stages");
    const Field contact = entry.child("contact");
    double contact_stiffness = 0.0;
    const Field arm_angle = entry.child("arm_angle");
    const bool mechanism = model_field.present() && model_field.text() == "arm_en50318";
    if (arm_angle.present() && !mechanism)
      arm_angle.fail(
          "arm_angle places the arm of `model: arm_en50318`; this pantograph has " +
          std::string(model_field.present() ? "model: " + model_field.text() : "stages") +
          ", no arm");
    if (model_field.present()) {
      if (model_field.text() != "en50318" && !mechanism)
        model_field.fail("unknown pantograph model '" + model_field.text() +
                         "'; accepted: en50318 (the reference two-stage model), arm_en50318 "
                         "(a single-arm mechanism of rigid bodies equivalent to it at its "
                         "design height), or give `stages` instead");
      if (stages_field.present())
        stages_field.fail("`model: " + model_field.text() +
                          "` defines the stages; give either model or stages");
      stages = en50318_stages();
      contact_stiffness = kEn50318ContactStiffness;
    } else {
      if (!stages_field.present())
        entry.fail(
            "missing `stages` (head first: [{mass, stiffness, damping}, ...]) or "
            "`model: en50318`");
      stages = read_stages(stages_field);
    }
    if (contact.present()) {
      contact.expect_map("contact settings {type, stiffness, damping}");
      contact.check_keys({"type", "stiffness", "damping"});
      const Field type = contact.child("type");
      const std::string kind = type.text_or("penalty");
      if (kind != "penalty" && kind != "bilateral")
        type.fail("unknown contact type '" + kind +
                  "'; expected penalty (a spring that lets go: the default) or bilateral (a "
                  "multiplier that holds the head on the wire)");
      c.bilateral = kind == "bilateral";
      if (c.bilateral) {
        for (const char* key : {"stiffness", "damping"})
          if (const Field f = contact.child(key); f.present())
            f.fail(std::string("a bilateral contact has no ") + key +
                   " (the head is held on the wire); remove it, or use type: penalty");
        check_bilateral_contact(type, m, c);
      } else {
        contact_stiffness =
            contact.child("stiffness").real_or(contact_stiffness, RealRange::positive("N/m"));
        c.damping = contact.child("damping").real_or(0.0, RealRange::non_negative("N*s/m"));
      }
    }
    if (contact_stiffness <= 0.0 && !c.bilateral)
      entry.fail("missing contact: {stiffness: k_c} (N/m); `model: en50318` sets 50000");
    c.stiffness = c.bilateral ? 0.0 : contact_stiffness;
    c.up = up;
    for (const Stage& s : stages) c.stages.push_back({s.mass, s.stiffness, s.damping});
    c.static_force = static_force;
    c.aerodynamic_coefficient = aero;

    const int origin = build.add_origin(entry);
    if (mechanism) {
      // The head touches the wire where the scene draws it: off the path, the air spring
      // would throw the arm up with nothing to hold it.
      if (c.start < 0.0 || c.start > path_length)
        entry.child("start").fail(
            "a pantograph of model arm_en50318 must start under its wire (its head touches "
            "the wire in the scene's configuration): start " +
            format_number(c.start) + " m, the path from 0 to " + format_number(path_length) + " m");
      const Vec3 travel =
          travel_direction(m, m.paths[static_cast<size_t>(c.path)], c.start, path_length);
      build_arm_pantograph(build, origin, entry, c, contact_point, travel,
                           static_force + aero * c.speed * c.speed, next_node_id);
      check_mechanism_analysis(model_field, m);
    } else {
      add_stages(build, origin, stages, c, contact_point, static_force + aero * c.speed * c.speed,
                 next_node_id, next_element_id);
    }
    if (c.bilateral) {
      Constraint k;
      k.type = ConstraintType::contact;
      k.node_a = c.head_node;
      k.contact = static_cast<int>(m.contacts.size());
      k.equations = 1;
      c.constraint = static_cast<int>(m.constraints.size());
      m.constraints.push_back(k);
    }
    m.contacts.push_back(c);
    // The integrator was checked before the pantographs were read: once more, now that a
    // bilateral contact may have added a constraint.
    if (c.bilateral && m.analysis == AnalysisType::dynamic)
      if (const auto refusal = refuse_integrator(m.dynamic_options.integrator, m.constraints.size(),
                                                 !m.rigid_bodies.empty() || !m.sliders.empty()))
        contact.child("type").fail(refusal->why);
  }
}

}  // namespace catena::model::detail
