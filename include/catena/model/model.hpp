#pragma once
// The validated description of what to simulate: plain data, no behaviour. Produced by
// the scene reader (scene_reader.hpp) on every rank from the same text, consumed by the
// assembly layer. Indices are 0-based positions in the vectors below; user-facing ids
// (as written in the scene) are kept for messages and output. Units are SI throughout.
#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "catena/core/vec3.hpp"
#include "catena/model/catenary_layout.hpp"
#include "catena/model/element_props.hpp"  // ElementProps, Rayleigh
#include "catena/model/shared_props.hpp"

namespace catena::model {

struct Node {
  std::int64_t id = 0;           // user id (generated ids for line interior nodes)
  Vec3 position = Vec3::Zero();  // m, reference (mesh) position
  // Reference nodal frame, set by the scene reader from the attached elements:
  // tangent = ∂r/∂x (unit) where a cable or beam attaches (zero otherwise; all attached
  // cables/beams must be collinear there, ANCF slopes being continuous at a node);
  // section_y/section_z = ∂r/∂y, ∂r/∂z (unit, orthogonal to tangent) where a beam attaches.
  Vec3 tangent = Vec3::Zero();
  Vec3 section_y = Vec3::Zero();
  Vec3 section_z = Vec3::Zero();
};

struct ElementDesc {
  std::int64_t id = 0;
  // Node indices. Every element kind joins two nodes; a fixed pair, not a vector, because
  // every rank holds every element (16 bytes and a heap block less each: 1.8 MiB on a
  // 10 km line).
  std::array<int, 2> nodes{};
  SharedProps props;  // shared with the elements of the same values (shared_props.hpp)
  Vec3 distributed_load = Vec3::Zero();  // N/m per unit mesh length (cable, beam)
  std::string set;                       // name of the line / set it belongs to ("" = none)
};

// Fixed DOFs of a node, eliminated from the system. Bits index the nodal layout
// [x, y, z, r_x(3), r_y(3), r_z(3)]; fixed values are those of the reference
// configuration. "pinned" fixes 0..2. "clamped" fixes the position (0..2), a beam's
// section frame (6..11) and the direction of the slope r_x: r_x = s·t with t the node's
// reference tangent and s (the stretch there) free, one unknown instead of three
// (slope_direction; assembly/dof_map.hpp). A component list fixes exactly its components.
struct Support {
  int node = 0;
  unsigned fixed_mask = 0;       // bit k fixes nodal DOF k
  bool slope_direction = false;  // r_x = s·tangent, s free (the slope's bits are not set)
  // The bits of fixed_mask that only keep a 2D model in its plane (y and slope y of a 2D
  // catenary's nodes): a modelling restriction, not a support, so a node held by them alone
  // has no reaction output (model/supported_nodes.hpp).
  unsigned plane_mask = 0;
};

// Where a support holds its node's position and slope r_x, if not at its reference: the
// static start of a catenary window holds its ends where the line has them (set by the
// run, never by a scene: the elements keep the reference geometry).
struct HeldPlace {
  int node = 0;
  Vec3 position = Vec3::Zero();  // m
  Vec3 slope = Vec3::Zero();     // r_x
};

// A rigid plane that nodes may touch (elements/surface_contact.hpp): a unilateral penalty
// contact with damping and regularised Coulomb friction on each of `nodes`.
struct Surface {
  std::string name;
  Vec3 point = Vec3::Zero();    // m, a point of the plane
  Vec3 normal = Vec3::UnitZ();  // unit, towards the free side
  double stiffness = 0.0;       // N/m
  double damping = 0.0;         // N·s/m
  double friction = 0.0;        // Coulomb coefficient
  double stick_speed = 1e-3;    // m/s
  std::vector<int> nodes;       // node indices, ascending
};

// The end of a cable line cut from a longer line (elements/absorbing_end.hpp): held where
// it is in statics; in a dynamic run free, pulled by its force at the run's initial state
// and by dashpots matched to the line's wave impedances, so that waves leave the model.
struct AbsorbingEnd {
  int node = 0;     // model node index: the end of exactly one element, a cable
  int element = 0;  // that element's index
};

// Linear spring (and dashpot) from a node's position to ground.
struct ElasticSupport {
  int node = 0;
  Vec3 stiffness = Vec3::Zero();  // N/m
  Vec3 damping = Vec3::Zero();    // N·s/m
};

// A kinematic constraint on node positions, enforced by Lagrange multipliers λ (three per
// constraint, one per global axis) rather than by eliminating DOFs, so it can join nodes
// of different lines (a clamp), hold a node with its slopes free, or drive a node along a
// prescribed path. g(q, t) = 0 with
//   coincident:  g = r_A − r_B
//   pinned:      g = r_A − X_A
//   prescribed:  g = r_A − X_A − u(t),  u(t) = velocity·t + amplitude·sin(2π·frequency·t)
// (X_A: reference position, so the reference configuration satisfies g(q_ref, 0) = 0).
// λ is the force the constraint applies to node A, with the sign convention
// M a + f + Gᵀλ = 0 (G = ∂g/∂q): the force on A is −λ (on B, +λ).
//
// A rigid body's node (RigidBody) carries two more, added by the scene reader, that keep
// its axes e1, e2, e3 orthonormal; they are quadratic in q, so their G depends on q:
//   frame_lengths:  g_k = ½(e_k·e_k − 1),           k = 1, 2, 3
//   frame_angles:   g = (e2·e3, e3·e1, e1·e2)
// Their multipliers are generalised forces on the axes (N·m), not forces on the node.
//
// A joint (`joints` in the scene, model::Joint) is one constraint of type `joint` whose
// multipliers are its equations (3 to 6: couplings/joint_constraint.hpp).
//
// A slider (`sliders` in the scene, model::Slider) is one constraint of type `slider` on its
// node: g = r_A − r_path(s), s the node's fourth unknown (couplings/slider_constraint.hpp).
//
// A pantograph with a bilateral contact (model::MovingContact::bilateral) is one constraint
// of type `contact` on its head: g = (r_head − r_wire(s(t)))·up, its multiplier the contact
// force (couplings/bilateral_contact.hpp).
enum class ConstraintType {
  coincident,
  pinned,
  prescribed,
  frame_lengths,
  frame_angles,
  joint,
  slider,
  contact
};

struct Constraint {
  ConstraintType type = ConstraintType::pinned;
  int node_a = 0;
  int node_b = -1;                // coincident only
  Vec3 velocity = Vec3::Zero();   // m/s, prescribed only
  Vec3 amplitude = Vec3::Zero();  // m, prescribed only
  double frequency = 0.0;         // Hz, prescribed only
  int joint = -1;                 // joint only: index into Model::joints
  int slider = -1;                // slider only: index into Model::sliders
  int contact = -1;               // contact only: index into Model::contacts
  int equations = 3;              // its multipliers (a joint's: 3 to 6)
};

// A joint between a rigid body and another body, a node of the structure or the ground
// (`joints` in the scene), enforced as one constraint (type `joint`) whose multipliers are
// its equations (couplings/joint_constraint.hpp). With X the joint's point and u its axis
// in the reference configuration (which satisfies the equations), the body A and the other
// side B:
//   spherical    A's point X stays at B's                                        3 equations
//   revolute     ... and A's axis stays along B's: rotation about u only          5
//   cylindrical  A's axis stays on B's line through X: rotation about and sliding
//                along u                                                          4
//   prismatic    ... and no rotation about u: sliding along u only               5
//   fixed        A's point and axes stay B's: welded                             6
// A node side (spherical only) is the node's position; the ground side is fixed.
enum class JointType { spherical, revolute, cylindrical, prismatic, fixed };

struct Joint {
  std::string name;
  JointType type = JointType::spherical;
  int body_a = 0;             // index into Model::rigid_bodies
  int body_b = -1;            // index into Model::rigid_bodies, or −1 (a node or the ground)
  int node_b = -1;            // a node that is no body's (spherical joints), or −1
  Vec3 point = Vec3::Zero();  // m, global, reference configuration
  Vec3 axis = Vec3::UnitZ();  // unit, global, reference (revolute, cylindrical, prismatic)
  // Revolute and prismatic joints: a spring, a dashpot and an actuator on the joint's
  // coordinate ξ (the rotation of A relative to B about the axis, rad, in (−π, π] from the
  // reference; or A's slide along it, m): the generalised force on ξ is
  //   −stiffness (ξ − neutral) − damping ξ̇ + actuator     (couplings/joint_spring.hpp).
  double stiffness = 0.0;  // N·m/rad or N/m
  double damping = 0.0;    // N·m·s/rad or N·s/m
  double neutral = 0.0;    // rad or m
  double actuator = 0.0;   // N·m or N, constant
  // The neutral may move, ξ₀(t) = neutral + neutral_velocity·t + neutral_amplitude·sin(2π·
  // neutral_frequency·t): the spring and dashpot then act on ξ − ξ₀(t) and ξ̇ − ξ̇₀(t), a
  // position servo with proportional (stiffness) and derivative (damping) gains.
  double neutral_velocity = 0.0;   // rad/s or m/s
  double neutral_amplitude = 0.0;  // rad or m
  double neutral_frequency = 0.0;  // Hz
  // The largest torque (force) the spring, dashpot and actuator together apply (a motor's
  // limit), reached smoothly: P = limit·tanh(u/limit) of their sum u. 0: no limit.
  double limit = 0.0;  // N·m or N
  // Dry friction in the joint: a torque (force) of magnitude `friction` against ξ̇,
  // regularised as friction·ξ̇/√(ξ̇² + stick_speed²) (as a slider's Coulomb friction).
  double friction = 0.0;      // N·m or N
  double stick_speed = 1e-3;  // rad/s or m/s
  // Whether anything above acts on the coordinate (a couplings::JointSpring to evaluate).
  bool has_coordinate_force() const {
    return stiffness != 0.0 || damping != 0.0 || actuator != 0.0 || friction != 0.0;
  }
  // Revolute and prismatic joints: a prescribed motion of the coordinate instead,
  //   ξ(t) = motion_velocity·t + motion_amplitude·sin(2π·motion_frequency·t)  (rad or m),
  // one more equation whose multiplier is the driving torque or force.
  bool driven = false;
  double motion_velocity = 0.0;   // rad/s or m/s
  double motion_amplitude = 0.0;  // rad or m
  double motion_frequency = 0.0;  // Hz
};

// Equations (multipliers) of a joint of this type, without a prescribed motion.
inline int joint_equations(JointType type) {
  switch (type) {
    case JointType::spherical:
      return 3;
    case JointType::revolute:
      return 5;
    case JointType::cylindrical:
      return 4;
    case JointType::prismatic:
      return 5;
    case JointType::fixed:
      return 6;
  }
  return 0;
}
// Equations (multipliers) of a joint: its type's, and one for a prescribed motion.
inline int joint_equations(const Joint& joint) {
  return joint_equations(joint.type) + (joint.driven ? 1 : 0);
}

struct NodalLoad {
  int node = 0;
  Vec3 force = Vec3::Zero();  // N, dead load
};

struct PointMass {
  int node = 0;
  double mass = 0.0;  // kg
};

// A rigid body in natural coordinates on one node (docs/formulation.md, "Rigid bodies"):
// the node's unknowns are a body point r (the node) and the body's axes e1, e2, e3 in the
// global frame, so the body point at body coordinates ξ is at x = r + ξ_k e_k, linear in
// the unknowns, and the mass matrix is constant. The node's reference frame (Node::tangent,
// section_y, section_z) holds the axes' initial directions; two constraints (frame_lengths,
// frame_angles) keep them orthonormal.
struct RigidBody {
  std::string name;
  int node = 0;
  double mass = 0.0;                     // kg, > 0
  Vec3 centre_of_mass = Vec3::Zero();    // m, body coordinates of the centre of mass from r
  Mat3 inertia = Mat3::Zero();           // kg·m², about the centre of mass, in body axes
  Vec3 velocity = Vec3::Zero();          // m/s: initial velocity of r
  Vec3 angular_velocity = Vec3::Zero();  // rad/s: initial, global components
  int first_constraint = -1;  // index of its frame_lengths constraint (frame_angles follows)
};

struct StaticOptions {
  double initial_load_step = 1.0;  // first load increment tried (fraction of full load)
  double min_load_step = 1e-4;     // give up below this increment
  int max_load_steps = 200;        // give up after this many accepted + rejected steps
  double rtol = 1e-10;             // SNES relative residual tolerance
  double atol = 1e-8;              // SNES absolute residual tolerance (N)
  int max_newton_iterations = 30;  // per load step
  // Start from each line's closed-form elastic catenary where the model is made of lines
  // hanging under gravity alone (solvers/statics/hanging_cable_guess.hpp); false: always
  // walk the load path from the reference.
  bool elastic_catenary_guess = true;
};

struct OutputOptions {
  std::string file = "catena.h5";
  // Dynamics: state sampled every `interval` s of simulated time (0: every accepted step)
  // by the integrator's dense output; results flushed to disk at most every
  // `flush_wall_seconds` of wall time.
  double interval = 0.0;
  double flush_wall_seconds = 10.0;
  // Dynamics: a checkpoint (full integrator state, atomic write) every `checkpoint_wall_seconds`
  // of wall time (0: only at the end and on SIGTERM/SIGINT), to `file` + ".chk".
  double checkpoint_wall_seconds = 600.0;
};

enum class AnalysisType { static_equilibrium, dynamic };

// Time integrator settings (docs/integrators.md). `type` selects the method:
//   hht                                    HHT-α (alpha)
//   gauss, radau_iia, lobatto_iiia,        implicit Runge–Kutta in K-form with `stages`
//   lobatto_iiic, sdirk                    (see solvers/time/irk/butcher_tableau.hpp)
//   bdf (with `order`), park               linear multistep, variable step
//   abm (with `order`)                     Adams–Bashforth–Moulton PECE (explicit)
//   petsc                                  PETSc TS (-ts_type alpha2, bdf, rosw, theta, ...)
struct IntegratorOptions {
  std::string type = "hht";  // canonical names: "radau" is stored as "radau_iia"
  int stages = 3;            // IRK only
  int order = 2;             // bdf: 1 to 5 (above 2 with adaptive steps only); abm: 1, 2
  double alpha = -0.1;       // HHT only, ∈ [−1/3, 0]
  double dt = 1e-3;          // s: the step (fixed) or the first step (adaptive)
  bool adaptive = false;
  double rtol = 1e-4;     // local error, relative to the displacement from the reference
  double atol = 1e-6;     // local error, absolute (m for positions, 1 for slopes)
  double dt_min = 1e-10;  // s: below this an adaptive run stops with an error
  double dt_max = 0.0;    // s: 0 = no limit beyond the duration
  // auto: embedded where the method has one (Radau IIA odd s, HHT), else step doubling.
  std::string error_estimate = "auto";  // auto | embedded | step_doubling
  // simplified (frozen Jacobian) | full | linearly_implicit (HHT: one Newton step per time
  // step, fixed cost; the tangent re-evaluated every `tangent_every` steps, 0: never)
  std::string newton = "simplified";
  int tangent_every = 0;
  // IRK stage Newton: auto (decoupled where exact) | decoupled | coupled
  std::string linear_algebra = "auto";
  // HHT: finish Newton solves whose residual is left in a few windows by Newton on those
  // windows (solvers/newton/local_newton.hpp).
  bool local_newton = true;
  double newton_rtol = 1e-10;  // Newton residual tolerance, relative to the force scale
  double newton_atol = 1e-8;   // N
  int max_newton_iterations = 10;
};

// A displacement field added to the initial configuration (e.g. a plucked string).
struct InitialNodeOffset {
  int node = 0;
  Vec3 displacement = Vec3::Zero();  // m, added to r
  Vec3 slope = Vec3::Zero();         // added to ∂r/∂x (nodes with slopes only)
};

struct InitialConditions {
  bool from_static = true;  // start from the static equilibrium; else from the reference
  std::vector<InitialNodeOffset> offsets;
  Vec3 velocity = Vec3::Zero();  // m/s, uniform initial velocity of every free position DOF
};

// A node that runs along a chain of cable or beam elements (`sliders` in the scene; MBDyn's
// beam slider, HOTINT's sliding joint): its unknowns are its point r and its arc length s
// along `path` (UnknownKind::slider), held together by one constraint (type `slider`)
//   g = r − r_path(s) = 0,   r_path(s) = S1 r_A + S2 r_A,x + S3 r_B + S4 r_B,x
// on the path element holding s (arc length on the reference geometry, as a pantograph's).
// The ANCF slopes are shared at the nodes, so r_path and its tangent are continuous across
// element boundaries. The tangential part of the multipliers is the friction, viscous and
// Coulomb (regularised):
//   (∂r_path/∂s)·λ = damping·ṡ + friction·|t × λ|·ṡ/√(ṡ² + stick_speed²)
// (t = ∂r_path/∂s; |t × λ| is |t| times the normal force; zero: frictionless).
// The node carries no mass of its own along s; masses, springs and bars at it, or a body
// joined to it (a spherical joint), carry the trolley.
struct Slider {
  std::string name;
  int node = 0;               // its node (kind slider)
  int path = 0;               // index into Model::paths
  double start = 0.0;         // m: s in the reference configuration (where the node lies)
  double damping = 0.0;       // N·s/m along the path
  double friction = 0.0;      // Coulomb coefficient μ: |friction force| ≤ μ |normal force|
  double stick_speed = 1e-3;  // m/s: below it the Coulomb force grows with ṡ (regularised)
  int constraint = -1;        // index of its constraint (type slider)
};

// A constant force moving at constant speed along a chain of cable/beam elements
// (a pantograph's uplift as a dead load): at time t it acts at arc length
// s(t) = start + speed·(t − start_time) along `elements` (in path order, measured on the
// reference geometry), distributed by the element's shape functions; off the path it
// does nothing.
struct MovingLoad {
  std::string name;
  std::vector<int> elements;  // element indices in path order
  Vec3 force = Vec3::Zero();  // N
  double speed = 0.0;         // m/s
  double start = 0.0;         // m, arc length at start_time
  double start_time = 0.0;    // s
};

// A named chain of cable/beam elements in travel order (e.g. the contact wire a
// pantograph runs along), measured on the reference geometry. Made by the catenary
// builder or from a list of lines.
struct ElementPath {
  std::string name;
  std::vector<int> elements;  // element indices, consecutive elements share a node
};

// Penalty contact between a pantograph head (a node moving vertically) and a wire at the
// moving point s(t) = start + speed·t along `path` (arc length on the reference geometry):
// penetration δ = (r_head − r_wire(s))·up, force F = stiffness·δ + damping·δ̇ when δ > 0,
// pushing the wire along +up and the head along −up; zero when δ ≤ 0 (loss of contact).
// The head's coupling to every element of the path is preallocated, so the sparsity
// pattern is fixed for the run.
struct MovingContact {
  std::string name;         // the pantograph's name
  int head_node = 0;        // node index of the head
  int path = 0;             // index into Model::paths
  double speed = 0.0;       // m/s along the path: < 0 runs backward (direction: backward)
  double start = 0.0;       // m along the path at t = 0
  double stiffness = 0.0;   // N/m, k_c > 0
  double damping = 0.0;     // N·s/m (acts only in contact)
  Vec3 up = Vec3::UnitZ();  // unit contact direction (opposite to gravity)
  // `contact: {type: bilateral}`: the head held on the wire by a multiplier (the contact
  // force, which may turn negative) instead of the penalty spring; stiffness and damping
  // unused. Its constraint (type contact) is `constraint`.
  bool bilateral = false;
  int constraint = -1;
  // What the pantograph reader built, for `catena check` (the stages themselves are nodes,
  // point masses, springs, an elastic support and loads in the model's vectors).
  struct Stage {
    double mass = 0.0;       // kg
    double stiffness = 0.0;  // N/m, to the next stage (the last: to ground)
    double damping = 0.0;    // N·s/m, likewise
  };

  std::vector<Stage> stages;  // head first
  // `model: arm_en50318`: the head is a rigid body on an arm (model/pantograph_mechanism.hpp);
  // `stages` are then its equivalent stages at arm_angle (degrees above horizontal).
  bool mechanism = false;
  double arm_angle = 0.0;
  std::vector<int> mechanism_nodes;      // its bodies' nodes (head, arm)
  double static_force = 0.0;             // N, F0 on the last stage
  double aerodynamic_coefficient = 0.0;  // N·s²/m²: the uplift is F0 + c·speed²
};

// The nodes a pantograph added: its lumped stages (consecutive from the head) or its
// mechanism's bodies.
inline std::vector<int> pantograph_nodes(const MovingContact& c) {
  if (c.mechanism) return c.mechanism_nodes;
  std::vector<int> nodes;
  for (std::size_t k = 0; k < c.stages.size(); ++k)
    nodes.push_back(c.head_node + static_cast<int>(k));
  return nodes;
}

// analysis.structure: what of the structure's nonlinearity a dynamic run keeps.
enum class StructureModel {
  nonlinear,  // all of it (the default)
  // cables and beams (not tension-only ones) linearised about the initial static
  // equilibrium (elements/linearized.hpp); bars, springs, masses, constraints, loads and
  // contacts stay as they are
  linear,
  // the structure linearised about the static equilibrium, the catenary in its modes below
  // modal_cutoff, contacts and slack droppers as forces (solvers/modal/modal_model.hpp)
  modal,
};

// Hz: the default analysis.modal_cutoff. On EN 50318 at 250 km/h the statistics of the
// modal model are within 1 % of the linear structure's with the modes below 100 Hz (σ
// +0.24 %), 3.4 % off at 40 Hz (docs/integrators.md, "Modal model").
inline constexpr double kDefaultModalCutoff = 100.0;

struct DynamicOptions {
  double duration = 0.0;  // s, > 0
  StructureModel structure = StructureModel::nonlinear;
  double modal_cutoff = 0.0;  // Hz, analysis.modal_cutoff (structure: modal)
  // analysis.modal_basis (structure: modal): a file that holds the catenary's modes
  // (io/modal_basis.hpp), read if it is there and holds this structure's modes, else
  // written by the run; "" computes the modes and keeps nothing.
  std::string modal_basis;
  IntegratorOptions integrator;
  InitialConditions initial;
};

struct Model {
  std::string name;
  std::string source_file;        // path as given
  std::string source_text;        // the scene text after --set overrides, stored in output
  Vec3 gravity{0.0, 0.0, -9.81};  // m/s²

  std::vector<Node> nodes;
  std::vector<ElementDesc> elements;
  std::vector<Support> supports;
  std::vector<HeldPlace> held_places;  // supports holding their nodes elsewhere
  std::vector<ElasticSupport> elastic_supports;
  std::vector<AbsorbingEnd> absorbing_ends;
  std::vector<Surface> surfaces;
  std::vector<NodalLoad> nodal_loads;
  std::vector<PointMass> point_masses;
  std::vector<RigidBody> rigid_bodies;
  std::vector<Joint> joints;
  std::vector<Slider> sliders;
  std::vector<Constraint> constraints;

  std::vector<MovingLoad> moving_loads;
  std::vector<ElementPath> paths;
  std::vector<MovingContact> contacts;
  // Contact-wire nodes at registration (steady-arm) points: EN 50318's uplift at support.
  std::vector<int> registration_nodes;
  // The span of the line the contact statistics are evaluated on, [x_start, x_end] in m
  // along the first contact's path (both 0: not set).
  double evaluation_start = 0.0, evaluation_end = 0.0;
  // The acceptance ranges the run's contact-force statistics are checked against by
  // `catena stats` (catenary.acceptance): "en50318", or empty for none.
  std::string acceptance;

  AnalysisType analysis = AnalysisType::static_equilibrium;
  StaticOptions static_options;  // statics, and the initial equilibrium of dynamics
  DynamicOptions dynamic_options;
  OutputOptions output;

  // Set when the scene has a `catenary`: what the builder made and what shape finding
  // (catenary/shape_finding.hpp) adjusts; empty otherwise.
  std::optional<CatenaryLayout> catenary;
};

// Not collective. Σ Constraint::equations: the model's Lagrange multipliers.
inline int total_multipliers(const Model& model) {
  int total = 0;
  for (const Constraint& c : model.constraints) total += c.equations;
  return total;
}

// Not collective. The width of a constraint's row of multipliers in output and checkpoints:
// the most equations of any constraint of the model, at least 3 (a model of node and frame
// constraints only keeps the three columns it always had); shorter rows are padded with 0.
inline int multiplier_width(const Model& model) {
  int width = 3;
  for (const Constraint& c : model.constraints) width = std::max(width, c.equations);
  return width;
}

}  // namespace catena::model
