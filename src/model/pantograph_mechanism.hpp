#pragma once
// `model: arm_en50318`: a pantograph as a mechanism of rigid bodies instead of lumped
// stages (docs/scene.md, "pantographs"; docs/formulation.md, "Single-arm pantograph").
//
// An arm (a rigid body) turns on a revolute joint to the ground about the horizontal axis
// across the track; the head (a second body) slides along the vertical on a prismatic joint
// at the arm's tip, its suspension the joint's spring and dashpot; the contact acts on the
// head's body point, where the head touches the wire. The air spring is a vertical force at
// the arm's centre of mass that holds the arm's and the head's weight and the uplift at
// every height (a flat static characteristic, as a pantograph's air spring and cam give).
// The arm's torsion spring and dashpot at its base hold the frame.
//
// The parameters are designed, not published: at the design angle (30° above horizontal,
// 1.8 m arm) the mechanism's linearised motion is EN 50318's two-stage reference model
// (head 7.2 kg on 4200 N/m and 10 N s/m; frame 15 kg on 50 N/m and 90 N s/m). At another
// `arm_angle` the same mechanism works at another height, and its equivalent frame mass,
// stiffness and damping change with the kinematics (equivalent_stages below).
#include "catena/core/vec3.hpp"
#include "catena/model/model.hpp"
#include "scene_build.hpp"
#include "yaml_fields.hpp"

namespace catena::model::detail {

// The preset's physical parameters (SI).
struct ArmPantograph {
  double arm_length = 1.8;             // m, base pivot to tip
  double design_angle_deg = 30.0;      // where it is EN 50318's reference model
  double head_mass = 7.2;              // kg
  Vec3 head_inertia{2.2, 0.1, 2.2};    // kg m², about (travel, across, up)
  double suspension_stiffness = 4200;  // N/m
  double suspension_damping = 10;      // N s/m
  double frame_mass = 15.0;            // kg, EN 50318's m2: sets the arm's inertia
  double frame_stiffness = 50.0;       // N/m, EN 50318's k2: sets the torsion spring
  double frame_damping = 90.0;         // N s/m, EN 50318's c2: sets the torsion dashpot
  double arm_axial_inertia = 0.05;     // kg m², about the arm's own axis (a tube's)

  double lever(double angle_deg) const;  // L cos α: tip height per arm rotation, m
  // The arm (a uniform bar) whose inertia about its pivot makes the frame's equivalent mass
  // frame_mass at the design angle.
  double arm_mass() const;
  double torsion_stiffness() const;  // N m/rad
  double torsion_damping() const;    // N m s/rad
};

// EN 50318-style stages (head, frame) equivalent to the mechanism at `angle_deg` for small
// motions: m2 = I_pivot/(L cos α)² + m_h tan²α + I_h,across/(L cos α)²,
// k2 = k_θ/(L cos α)², c2 = c_θ/(L cos α)².
std::vector<MovingContact::Stage> equivalent_stages(const ArmPantograph& p, double angle_deg);

// Not collective. Builds the mechanism of pantograph `c` (its path, start and uplift read)
// with the head's body point at `contact_point`, the arm in the vertical plane through the
// horizontal `travel` direction; appends nodes (the head's, then the arm's) from
// `next_node_id`, the bodies, their frame constraints, the two joints and the air spring's
// load; sets c.head_node, c.stages (the equivalent stages at the arm's angle) and
// c.mechanism and c.mechanism_nodes. `entry` is the pantograph's (its arm_angle; its name
// for messages).
void build_arm_pantograph(SceneBuild& build, int origin, const Field& entry, MovingContact& c,
                          const Vec3& contact_point, const Vec3& travel, double uplift,
                          std::int64_t& next_node_id);

}  // namespace catena::model::detail
