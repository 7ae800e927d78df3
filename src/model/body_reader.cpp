#include "body_reader.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <string>
#include <vector>

#include "output_name.hpp"

namespace catena::model::detail {
namespace {

// The inertia about the centre of mass: [Ixx, Iyy, Izz] (principal, in body axes) or three
// rows of a symmetric matrix.
Mat3 read_inertia(const Field& field) {
  const std::string expected =
      "[Ixx, Iyy, Izz] (principal moments about the centre of mass, kg*m^2) or the 3x3 "
      "symmetric inertia matrix as three rows";
  if (!field.present()) field.fail("missing required key; expected " + expected);
  const std::vector<Field> items = field.items();
  Mat3 inertia = Mat3::Zero();
  const RealRange component = RealRange::any("kg*m^2");
  if (items.size() == 3 && items[0].is_scalar()) {
    const Vec3 diagonal = field.vec3(RealRange::positive("kg*m^2"));
    inertia = diagonal.asDiagonal();
  } else if (items.size() == 3 && items[0].is_list()) {
    for (int r = 0; r < 3; ++r) inertia.row(r) = items[static_cast<size_t>(r)].vec3(component);
    if ((inertia - inertia.transpose()).cwiseAbs().maxCoeff() >
        1e-12 * inertia.cwiseAbs().maxCoeff())
      field.fail("the inertia matrix " + field.value_text() + " is not symmetric; expected " +
                 expected);
  } else {
    field.fail("got " + field.value_text() + "; expected " + expected);
  }
  // A body's principal moments are positive and each is less than the sum of the other two
  // (equal only for a body of zero thickness). Natural coordinates need it strictly: their
  // mass matrix holds ½ tr(I) 1 − I, whose entries are the body's second moments ∫ρ ξ_k² dV.
  const Eigen::SelfAdjointEigenSolver<Mat3> eigen(inertia);
  const Vec3 p = eigen.eigenvalues();
  const double tolerance = 1e-9 * p.cwiseAbs().maxCoeff();
  if (!(p.minCoeff() > 0.0) || !(p[0] + p[1] > p[2] + tolerance))
    field.fail("the principal moments " + format_number(p[0]) + ", " + format_number(p[1]) + ", " +
               format_number(p[2]) +
               " kg*m^2 are not a solid body's: each must be positive and less than the sum "
               "of the other two (a body of zero thickness has a massless axis, which "
               "natural coordinates cannot carry)");
  return inertia;
}

// The initial axes e1, e2, e3 from `axes: [e1, e2]` (e1 normalised, e2 made orthogonal to
// it and normalised, e3 = e1 × e2); absent: the global axes.
void read_axes(const Field& field, Vec3& e1, Vec3& e2, Vec3& e3) {
  e1 = Vec3::UnitX();
  e2 = Vec3::UnitY();
  if (field.present()) {
    const std::vector<Field> items = field.items();
    if (items.size() != 2)
      field.fail("got " + field.value_text() +
                 "; expected the body's first two axes in global components, [[e1], [e2]] "
                 "(e3 = e1 x e2)");
    e1 = items[0].vec3(RealRange::any(""));
    e2 = items[1].vec3(RealRange::any(""));
    if (!(e1.norm() > 0.0)) items[0].fail("the axis e1 is zero; expected a nonzero vector");
    e1.normalize();
    if (!(e1.cross(e2).norm() > 1e-6 * e2.norm()))
      items[1].fail("the axis e2 " + items[1].value_text() +
                    " is zero or parallel to e1; expected a vector not along e1");
    e2 = (e2 - e2.dot(e1) * e1).normalized();
  }
  e3 = e1.cross(e2);
}

}  // namespace

void read_bodies(const Field& bodies, SceneBuild& build) {
  static const std::vector<std::string> keys{
      "name", "node", "mass", "inertia", "centre_of_mass", "axes", "velocity", "angular_velocity"};
  Model& model = build.model;
  for (const Field& entry : bodies.items()) {
    entry.expect_map("a rigid body {node, mass, inertia, ...}");
    entry.check_keys(keys);
    RigidBody body;
    const Field name = entry.child("name");
    body.name =
        read_output_name(name, "body " + std::to_string(model.rigid_bodies.size() + 1), "a body");
    // Joints name their sides by body name, node id or `ground` (joint_reader.cpp).
    if (body.name == "ground" || parse_integer(body.name))
      name.fail(
          "a body's name must not be 'ground' or an integer (joints name their sides by "
          "body name, node id or ground); got '" +
          body.name + "'");
    for (const RigidBody& other : model.rigid_bodies)
      if (other.name == body.name)
        name.fail("two bodies are named '" + body.name + "'; expected distinct names");
    const Field node_field = entry.child("node");
    if (!node_field.present()) node_field.fail("missing required key; expected a node id");
    body.node = build.resolve_node(node_field);
    Node& node = model.nodes[static_cast<size_t>(body.node)];
    for (const RigidBody& other : model.rigid_bodies)
      if (other.node == body.node)
        node_field.fail("node " + std::to_string(node.id) + " already carries rigid body '" +
                        other.name + "'; a node carries one body");
    if (node.tangent != Vec3::Zero())
      node_field.fail("node " + std::to_string(node.id) +
                      " is a node of a cable or beam; a rigid body needs a node of its own "
                      "(bars, springs and masses may attach to it): join the body to the line "
                      "through a constraint or a bar");
    body.mass = entry.child("mass").real(RealRange::positive("kg"));
    body.inertia = read_inertia(entry.child("inertia"));
    body.centre_of_mass = entry.child("centre_of_mass").vec3_or(Vec3::Zero(), RealRange::any("m"));
    read_axes(entry.child("axes"), node.tangent, node.section_y, node.section_z);
    body.velocity = entry.child("velocity").vec3_or(Vec3::Zero(), RealRange::any("m/s"));
    body.angular_velocity =
        entry.child("angular_velocity").vec3_or(Vec3::Zero(), RealRange::any("rad/s"));
    model.rigid_bodies.push_back(body);
  }
}

void add_body_frame_constraints(const Field& bodies, SceneBuild& build) {
  Model& model = build.model;
  const std::vector<Field> entries = bodies.items();
  for (size_t b = 0; b < model.rigid_bodies.size(); ++b) {
    RigidBody& body = model.rigid_bodies[b];
    for (const Support& s : model.supports)
      if (s.node == body.node && ((s.fixed_mask >> 3) != 0 || s.slope_direction))
        entries[b].child("node").fail(
            "node " + std::to_string(model.nodes[static_cast<size_t>(body.node)].id) +
            " carries rigid body '" + body.name +
            "' and a support that fixes some of its axes (e1_x ... e3_z); a body's "
            "orientation is held by its constraints: fix its position only ([x, y, z])");
    append_frame_constraints(model, body);
  }
}

void append_frame_constraints(Model& model, RigidBody& body) {
  body.first_constraint = static_cast<int>(model.constraints.size());
  for (const ConstraintType type : {ConstraintType::frame_lengths, ConstraintType::frame_angles}) {
    Constraint c;
    c.type = type;
    c.node_a = body.node;
    model.constraints.push_back(c);
  }
}

}  // namespace catena::model::detail
