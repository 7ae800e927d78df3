#include "pantograph_mechanism.hpp"

#include <cmath>
#include <string>

#include "body_reader.hpp"
#include "joint_reader.hpp"
#include "number_format.hpp"

namespace catena::model::detail {
namespace {

double radians(double degrees) { return degrees * M_PI / 180.0; }

// The body's name: the pantograph's, then the part (output groups /bodies/<name>).
std::string part_name(const MovingContact& c, const char* part) { return c.name + " " + part; }

}  // namespace

double ArmPantograph::lever(double angle_deg) const {
  return arm_length * std::cos(radians(angle_deg));
}

double ArmPantograph::arm_mass() const {
  const double lever0 = lever(design_angle_deg), tan0 = std::tan(radians(design_angle_deg));
  const double pivot_inertia =
      (frame_mass - head_mass * tan0 * tan0) * lever0 * lever0 - head_inertia[1];
  return 3.0 * pivot_inertia / (arm_length * arm_length);  // a uniform bar: I = m L²/3
}

double ArmPantograph::torsion_stiffness() const {
  return frame_stiffness * lever(design_angle_deg) * lever(design_angle_deg);
}

double ArmPantograph::torsion_damping() const {
  return frame_damping * lever(design_angle_deg) * lever(design_angle_deg);
}

std::vector<MovingContact::Stage> equivalent_stages(const ArmPantograph& p, double angle_deg) {
  const double lever = p.lever(angle_deg), tan_a = std::tan(radians(angle_deg));
  const double pivot_inertia = p.arm_mass() * p.arm_length * p.arm_length / 3.0;
  const double l2 = lever * lever;
  return {{p.head_mass, p.suspension_stiffness, p.suspension_damping},
          {(pivot_inertia + p.head_inertia[1]) / l2 + p.head_mass * tan_a * tan_a,
           p.torsion_stiffness() / l2, p.torsion_damping() / l2}};
}

void build_arm_pantograph(SceneBuild& build, int origin, const Field& entry, MovingContact& c,
                          const Vec3& contact_point, const Vec3& travel, double uplift,
                          std::int64_t& next_node_id) {
  Model& m = build.model;
  const ArmPantograph p;
  const Field angle = entry.child("arm_angle"), name = entry.child("name");
  const double alpha = angle.real_or(
      p.design_angle_deg, RealRange::between(10.0, true, 60.0, true, "degrees above horizontal"));
  // (+ 0 turns the −0 components of products into 0 for the summary's printing.)
  const Vec3 up = c.up + Vec3::Zero();
  const Vec3 across = up.cross(travel).normalized() + Vec3::Zero();  // the joints' axis
  const Vec3 along = std::cos(radians(alpha)) * travel + std::sin(radians(alpha)) * up;
  const Vec3 tip = contact_point;  // the head's slide axis meets the arm's tip at the head
  const Vec3 pivot = tip - p.arm_length * along;
  const double g = m.gravity.norm();
  const double arm_mass = p.arm_mass();

  auto add_body_node = [&](const Vec3& position, const Vec3& e1, const Vec3& e2) {
    Node node;
    node.id = next_node_id++;
    node.position = position;
    build.add_node(node, origin);
    Node& added = m.nodes.back();
    added.tangent = e1;  // a body's initial axes (body_reader.cpp)
    added.section_y = e2;
    added.section_z = e1.cross(e2);
    return static_cast<int>(m.nodes.size()) - 1;
  };
  // The head first: c.head_node is it, and the travel of pictures moves head and arm.
  RigidBody head;
  head.name = part_name(c, "head");
  head.node = add_body_node(contact_point, travel, across);
  head.mass = p.head_mass;
  head.inertia = p.head_inertia.asDiagonal();
  RigidBody arm;
  arm.name = part_name(c, "arm");
  arm.node = add_body_node(pivot + 0.5 * p.arm_length * along, along, across);
  arm.mass = arm_mass;
  const double bar = arm_mass * p.arm_length * p.arm_length / 12.0;
  arm.inertia = Vec3(p.arm_axial_inertia, bar, bar).asDiagonal();
  const int head_index = static_cast<int>(m.rigid_bodies.size());
  for (RigidBody* body : {&head, &arm}) {
    for (const RigidBody& other : m.rigid_bodies)
      if (other.name == body->name)
        name.fail("the pantograph's body '" + body->name +
                  "' has the name of a body of the scene; rename one of them");
    m.rigid_bodies.push_back(*body);
    append_frame_constraints(m, m.rigid_bodies.back());
  }

  Joint base;
  base.name = part_name(c, "base pivot");
  base.type = JointType::revolute;
  base.body_a = head_index + 1;
  base.point = pivot;
  base.axis = across;
  base.stiffness = p.torsion_stiffness();
  base.damping = p.torsion_damping();
  append_joint(m, base);
  // The suspension holds the head where the scene draws it under the uplift and its weight.
  Joint suspension;
  suspension.name = part_name(c, "head suspension");
  suspension.type = JointType::prismatic;
  suspension.body_a = head_index;
  suspension.body_b = head_index + 1;
  suspension.point = tip;
  suspension.axis = up;
  suspension.stiffness = p.suspension_stiffness;
  suspension.damping = p.suspension_damping;
  suspension.neutral = (uplift + p.head_mass * g) / p.suspension_stiffness;
  append_joint(m, suspension);
  // The air spring: at the arm's centre of mass (half the tip's lever), twice what the tip
  // must carry, plus the arm's weight.
  m.nodal_loads.push_back({arm.node, up * (2.0 * (uplift + p.head_mass * g) + arm_mass * g)});

  c.head_node = head.node;
  c.mechanism_nodes = {head.node, arm.node};
  c.stages = equivalent_stages(p, alpha);
  c.mechanism = true;
  c.arm_angle = alpha;
}

}  // namespace catena::model::detail
