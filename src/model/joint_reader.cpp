#include "joint_reader.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "did_you_mean.hpp"
#include "number_format.hpp"
#include "sine_motion.hpp"

namespace catena::model::detail {
namespace {

const std::vector<std::string>& joint_type_names() {
  static const std::vector<std::string> names{"spherical", "revolute", "cylindrical", "prismatic",
                                              "fixed"};
  return names;
}

JointType read_joint_type(const Field& type) {
  if (!type.present())
    type.fail(
        "missing required key; expected one of spherical, revolute, cylindrical, "
        "prismatic, fixed");
  const std::string name = type.text();
  const std::vector<std::string>& names = joint_type_names();
  for (size_t k = 0; k < names.size(); ++k)
    if (name == names[k]) return static_cast<JointType>(k);
  type.fail("unknown joint type '" + name + "';" + did_you_mean(name, names) +
            " expected spherical (a shared point), revolute (a point and an axis: rotation "
            "about it), cylindrical (rotation about and sliding along an axis), prismatic "
            "(sliding along an axis) or fixed (welded)");
}

// A side of the joint: a body (by name), a node (by id, an integer) or `ground`.
struct SideRef {
  int body = -1;
  int node = -1;
  bool ground = false;
};

SideRef read_side(const Field& field, const SceneBuild& build) {
  const std::string expected = "a rigid body's name, a node id (an integer) or ground";
  if (!field.is_scalar()) field.fail("got " + field.value_text() + "; expected " + expected);
  const std::string text = field.text();
  if (text == "ground") return {-1, -1, true};
  const std::vector<RigidBody>& bodies = build.model.rigid_bodies;
  for (size_t b = 0; b < bodies.size(); ++b)
    if (bodies[b].name == text) return {static_cast<int>(b), -1, false};
  if (parse_integer(text)) {
    SideRef side;
    side.node = build.resolve_node(field);
    for (size_t b = 0; b < bodies.size(); ++b)
      if (bodies[b].node == side.node)
        field.fail("node " + text + " is rigid body '" + bodies[b].name +
                   "''s point; name the body instead (its joint point is 'point')");
    return side;
  }
  std::vector<std::string> names{"ground"};
  for (const RigidBody& b : bodies) names.push_back(b.name);
  field.fail("no rigid body is named '" + text + "';" + did_you_mean(text, names) + " expected " +
             expected);
}

}  // namespace

void read_joints(const Field& joints, SceneBuild& build) {
  static const std::vector<std::string> keys{
      "name",    "type",    "between",  "point", "axis",     "motion",      "stiffness",
      "damping", "neutral", "actuator", "limit", "friction", "stick_speed", "neutral_motion"};
  Model& model = build.model;
  for (const Field& entry : joints.items()) {
    entry.expect_map("a joint {type, between, point, axis}");
    entry.check_keys(keys);
    Joint joint;
    joint.name = entry.child("name").text_or("joint " + std::to_string(model.joints.size() + 1));
    joint.type = read_joint_type(entry.child("type"));
    const Field between = entry.child("between");
    if (!between.present())
      between.fail(
          "missing required key; expected [A, B]: A a rigid body's name, B a body's "
          "name, a node id or ground");
    const std::vector<Field> sides = between.items();
    if (sides.size() != 2)
      between.fail("expected two sides [A, B], got " + std::to_string(sides.size()));
    const SideRef a = read_side(sides[0], build), b = read_side(sides[1], build);
    if (a.body < 0)
      sides[0].fail(
          "the first side of a joint must be a rigid body (the second may be a body, "
          "a node or ground); got " +
          sides[0].value_text());
    if (a.body == b.body)
      sides[1].fail("a joint joins two different sides; got body '" +
                    model.rigid_bodies[static_cast<size_t>(a.body)].name + "' twice");
    joint.body_a = a.body;
    joint.body_b = b.body;
    joint.node_b = b.node;
    if (b.node >= 0 && joint.type != JointType::spherical)
      sides[1].fail("a node has no axes of its own: a " +
                    joint_type_names()[static_cast<size_t>(joint.type)] +
                    " joint needs a body or ground there (a node takes a spherical joint)");

    const Field point = entry.child("point");
    if (b.node >= 0) {
      // The node is the joint's point on its side.
      joint.point = model.nodes[static_cast<size_t>(b.node)].position;
      if (point.present()) {
        const Vec3 given = point.vec3(RealRange::any("m"));
        if ((given - joint.point).norm() > 1e-9 * std::max(1.0, joint.point.norm()))
          point.fail("the joint's point must be node " + sides[1].text() + "'s position " +
                     format_vector(joint.point) + " m (the node is the joint's point); got " +
                     point.value_text() + " (or leave 'point' out)");
      }
    } else {
      if (!point.present())
        point.fail(
            "missing required key; expected the joint's point [x, y, z] in m (global, "
            "reference configuration)");
      joint.point = point.vec3(RealRange::any("m"));
    }
    const Field axis = entry.child("axis");
    const bool has_axis = joint.type == JointType::revolute ||
                          joint.type == JointType::cylindrical ||
                          joint.type == JointType::prismatic;
    if (has_axis) {
      if (!axis.present())
        axis.fail(
            "missing required key; expected the joint's axis [x, y, z] (global, "
            "reference configuration, nonzero)");
      joint.axis = axis.vec3(RealRange::any(""));
      if (!(joint.axis.norm() > 0.0)) axis.fail("the axis is zero; expected a nonzero vector");
      joint.axis.normalize();
    } else if (axis.present()) {
      axis.fail("a " + joint_type_names()[static_cast<size_t>(joint.type)] +
                " joint has no axis; remove 'axis'");
    }

    // A spring, a dashpot and an actuator on the coordinate of a revolute or prismatic joint.
    const bool revolute = joint.type == JointType::revolute;
    const bool sliding = joint.type == JointType::prismatic;
    const char* spring_keys[] = {"stiffness", "damping",  "neutral",     "actuator",
                                 "limit",     "friction", "stick_speed", "neutral_motion"};
    for (const char* key : spring_keys)
      if (const Field field = entry.child(key); field.present() && !revolute && !sliding)
        field.fail("a " + joint_type_names()[static_cast<size_t>(joint.type)] +
                   " joint has no coordinate for '" + key +
                   "'; springs, dampers and actuators act on revolute (an angle) and prismatic "
                   "(a slide) joints");
    const std::string unit = revolute ? "rad" : "m";
    joint.stiffness = entry.child("stiffness")
                          .real_or(0.0, RealRange::non_negative(revolute ? "N*m/rad" : "N/m"));
    joint.damping = entry.child("damping").real_or(
        0.0, RealRange::non_negative(revolute ? "N*m*s/rad" : "N*s/m"));
    joint.neutral = revolute ? entry.child("neutral").real_or(
                                   0.0, RealRange::between(-M_PI, false, M_PI, true, unit))
                             : entry.child("neutral").real_or(0.0, RealRange::any(unit));
    joint.actuator = entry.child("actuator").real_or(0.0, RealRange::any(revolute ? "N*m" : "N"));
    const std::string force_unit = revolute ? "N*m" : "N";
    // A moving neutral: the spring and dashpot become a position servo tracking it.
    if (const Field motion = entry.child("neutral_motion"); motion.present()) {
      if (joint.stiffness == 0.0 && joint.damping == 0.0)
        motion.fail(
            "a moving neutral is what the spring and dashpot follow, and this joint has "
            "neither; give stiffness (the servo's proportional gain) and/or damping (its "
            "derivative gain), or leave neutral_motion out");
      motion.expect_map("a moving neutral {velocity, amplitude, frequency}");
      motion.check_keys({"velocity", "amplitude", "frequency"});
      joint.neutral_velocity =
          motion.child("velocity").real_or(0.0, RealRange::any(revolute ? "rad/s" : "m/s"));
      joint.neutral_amplitude = motion.child("amplitude").real_or(0.0, RealRange::any(unit));
      joint.neutral_frequency =
          read_sine_frequency(motion.child("frequency"), joint.neutral_amplitude == 0.0, unit);
    }
    if (const Field limit = entry.child("limit"); limit.present()) {
      if (joint.stiffness == 0.0 && joint.damping == 0.0 && joint.actuator == 0.0)
        limit.fail(
            "limit caps the torque (force) of the spring, dashpot and actuator, and this joint "
            "has none of them; give one, or leave limit out");
      joint.limit = limit.real(RealRange::positive(force_unit));
      if (std::abs(joint.actuator) >= joint.limit)
        limit.fail("the actuator's " + format_number(joint.actuator) + " " + force_unit +
                   " is not below the limit " + format_number(joint.limit) + " " + force_unit +
                   ": the limit would cut it; raise the limit or lower the actuator");
    }
    joint.friction = entry.child("friction").real_or(0.0, RealRange::non_negative(force_unit));
    const Field stick = entry.child("stick_speed");
    if (stick.present() && !(joint.friction > 0.0))
      stick.fail(
          "stick_speed regularises the joint's dry friction, and this joint has none; give "
          "friction (a torque or force > 0) or leave stick_speed out");
    joint.stick_speed =
        stick.real_or(joint.stick_speed, RealRange::positive(revolute ? "rad/s" : "m/s"));
    // A prescribed motion of the coordinate, as a node's: ξ(t) = velocity·t + amplitude·sin(2πft).
    if (const Field motion = entry.child("motion"); motion.present()) {
      if (!revolute && !sliding)
        motion.fail("a " + joint_type_names()[static_cast<size_t>(joint.type)] +
                    " joint has no coordinate to move; a prescribed motion drives a revolute "
                    "(an angle) or prismatic (a slide) joint");
      if (joint.has_coordinate_force())
        motion.fail(
            "a joint with a prescribed motion takes no stiffness, damping, actuator or "
            "friction (the motion is imposed whatever they do); remove one or the other "
            "(a spring that follows a motion: neutral_motion)");
      motion.expect_map("a prescribed motion {velocity, amplitude, frequency}");
      motion.check_keys({"velocity", "amplitude", "frequency"});
      joint.driven = true;
      joint.motion_velocity =
          motion.child("velocity").real_or(0.0, RealRange::any(revolute ? "rad/s" : "m/s"));
      joint.motion_amplitude = motion.child("amplitude").real_or(0.0, RealRange::any(unit));
      joint.motion_frequency =
          read_sine_frequency(motion.child("frequency"), joint.motion_amplitude == 0.0, unit);
    }

    append_joint(model, joint);
  }
}

void append_joint(Model& model, const Joint& joint) {
  Constraint c;
  c.type = ConstraintType::joint;
  c.node_a = model.rigid_bodies[static_cast<size_t>(joint.body_a)].node;
  c.node_b =
      joint.body_b >= 0 ? model.rigid_bodies[static_cast<size_t>(joint.body_b)].node : joint.node_b;
  c.joint = static_cast<int>(model.joints.size());
  c.equations = joint_equations(joint);
  model.joints.push_back(joint);
  model.constraints.push_back(c);
}

}  // namespace catena::model::detail
