#pragma once
// The time-series HDF5 file of a dynamic run, in one place: every group, dataset and
// attribute name, with its shape, type and unit. The writer (transient_writer.cpp) and
// every reader — the XDMF description (transient_xdmf.cpp), the run reader of
// `catena stats` (contact_run_reader.cpp), the run id of a restart (run_files.cpp) —
// use these names and no others; docs/output.md ("Time series") lists the same.
// Changing a name or a meaning means a new `format` string.
//
// Shapes are in HDF5 (row-major) order; n_samples and n_steps grow as the run goes on.
// Types are little-endian: float64, int64, int32.
#include <hdf5.h>

#include <string>

#include "mesh_layout.hpp"

namespace catena::io::transient_layout {

// The root attribute `format` of every time-series file; readers refuse any other.
inline constexpr const char* format = "catena-transient-1";

// A dataset: its absolute path and the string attribute `unit` it carries (nullptr: none,
// for indices, ids and counts).
struct Dataset {
  const char* path;
  const char* unit;
};

// ---- /mesh: the reference mesh, as in the static file (mesh_layout.hpp). ----
inline constexpr const char* mesh_group = mesh_layout::group;
inline constexpr Dataset node_ids{mesh_layout::node_ids, nullptr};  // (n_nodes,) int64
// (n_nodes, 3) float64: reference positions.
inline constexpr Dataset node_positions{mesh_layout::node_positions, "m"};
inline constexpr Dataset element_ids{mesh_layout::element_ids, nullptr};  // (n_elements,) int64
// (n_elements, 2) int64: node indices (0-based rows) of the first and last node.
inline constexpr Dataset element_nodes{mesh_layout::element_nodes, nullptr};
inline constexpr int nodes_per_element = mesh_layout::nodes_per_element;
// (n_elements,) int8 and int32: what each element is and the scene's set it belongs to
// (mesh_layout.hpp, element_classes.hpp).
inline constexpr Dataset element_kind{mesh_layout::element_kind, nullptr};
inline constexpr Dataset element_set{mesh_layout::element_set, nullptr};
// (n_constraints, 2) int64: node indices A and B of each constraint (B = −1: none). Only
// with constraints.
inline constexpr Dataset constraint_nodes{"/mesh/constraint_nodes", nullptr};
// (n_registration,) int64: node indices of the contact wire's registration points.
inline constexpr Dataset registration_nodes{"/mesh/registration_nodes", nullptr};
// (n_supports,) int64: node indices of the supported nodes (fixed DOFs or an elastic
// support), ascending: the rows of the reaction datasets. Only with supports.
inline constexpr Dataset support_nodes{"/mesh/support_nodes", nullptr};

// ---- Samples, one row per output time (output.interval apart). ----
inline constexpr Dataset time{"/time", "s"};  // (n_samples,) float64
// (n_samples, n_nodes, 3) float64: position, velocity and slope ∂r/∂x of every node.
inline constexpr Dataset positions{"/samples/positions", "m"};
inline constexpr Dataset velocities{"/samples/velocities", "m/s"};
inline constexpr Dataset slopes{"/samples/slopes", "1"};
// (n_samples, n_elements) float64: axial force at the element's mid-point.
inline constexpr Dataset axial_force{"/samples/axial_force", "N"};
// (n_samples, n_constraints, 3) float64: the force on node A. Only with constraints.
inline constexpr Dataset constraint_forces{"/samples/constraint_forces", "N"};
// (n_samples, n_supports, 3) float64: the force and the couple each support applies to
// its node (rows: /mesh/support_nodes). Only with supports.
inline constexpr Dataset reaction_force{"/samples/reaction_force", "N"};
inline constexpr Dataset reaction_moment{"/samples/reaction_moment", "N m"};
// (n_samples, n_pantographs) float64, column j = the pantograph whose `index` is j. Only
// with pantographs.
inline constexpr Dataset contact_force{"/samples/contact_force", "N"};
inline constexpr Dataset contact_position{"/samples/contact_position", "m"};

// ---- Steps, one row per accepted step. ----
// (n_steps,) float64: end and size of the step, its weighted local error estimate.
inline constexpr Dataset step_time{"/steps/time", "s"};
inline constexpr Dataset step_dt{"/steps/dt", "s"};
inline constexpr Dataset step_error{"/steps/error", "1"};
// (n_steps,) int32: Newton iterations of the kept attempts, attempts rejected before it.
inline constexpr Dataset step_newton_iterations{"/steps/newton_iterations", nullptr};
inline constexpr Dataset step_rejected{"/steps/rejected", nullptr};
// (n_steps, n_pantographs) float64. Only with pantographs.
inline constexpr Dataset step_contact_force{"/steps/contact_force", "N"};
// (n_steps, n_registration_nodes) float64: z of each registration node (/mesh/
// registration_nodes, in that order) at the step's end, for the uplift at the supports
// from every step. Only with registration nodes.
inline constexpr Dataset step_registration_height{"/steps/registration_height", "m"};
// (n_samples,) and (n_steps,) int32: catenary.window only, how many times the window had
// moved by the sample or the step's end; the mesh's nodes are then window_shift_x × that
// further along x on the line (the samples' positions are the line's already).
inline constexpr Dataset window_moves{"/samples/window_moves", nullptr};
inline constexpr Dataset step_window_moves{"/steps/window_moves", nullptr};

// (n_samples, n_bodies, 4) float64: each rigid body's orientation, the unit quaternion
// (w, x, y, z) of its axes [e1 e2 e3] (w ≥ 0); (n_samples, n_bodies, 3): its angular
// velocity, global components. Rows: /mesh/body_nodes. Only with rigid bodies.
inline constexpr Dataset body_orientation{"/samples/body_orientation", "1"};
inline constexpr Dataset body_angular_velocity{"/samples/body_angular_velocity", "rad/s"};
// (n_bodies,) int64: node index of each rigid body's point r (its position is that node's
// row of /samples/positions). Only with rigid bodies.
inline constexpr Dataset body_nodes{"/mesh/body_nodes", nullptr};
// (n_samples, n_joints, 4, 3) float64: each joint's two links, for drawing the mechanism:
// the points A's node, the joint's point carried by A, the joint's point carried by B, B's
// node (B the ground or a node: the joint's point, or that node's position, twice)
// (assembly::StateView::joint_links). Only with joints.
inline constexpr Dataset joint_links{"/samples/joint_links", "m"};
// ---- Rigid bodies: a group /bodies/<name> each (the scene's name), attribute `index`
// (its row in the body datasets). ----
inline constexpr const char* bodies_group = "/bodies";
inline constexpr const char* body_index_attribute = "index";

// (n_samples, n_sliders) float64: each slider's arc length s along its path (m) and its rate
// ṡ (m/s). Rows: /mesh/slider_nodes. Only with sliders.
inline constexpr Dataset slider_position{"/samples/slider_position", "m"};
inline constexpr Dataset slider_speed{"/samples/slider_speed", "m/s"};
// (n_sliders,) int64: node index of each slider (its point is that node's row of
// /samples/positions). Only with sliders.
inline constexpr Dataset slider_nodes{"/mesh/slider_nodes", nullptr};
// ---- Sliders: a group /sliders/<name> each, attributes `index` (its row in the slider
// datasets) and `constraint` (its row of /samples/constraint_forces). ----
inline constexpr const char* sliders_group = "/sliders";
inline constexpr const char* slider_constraint_attribute = "constraint";

// ---- Pantographs: a group /pantographs/<name> each (the scene's name). ----
inline constexpr const char* pantographs_group = "/pantographs";
namespace pantograph_attribute {
inline constexpr const char* index = "index";  // int64: its column in the contact datasets
inline constexpr const char* speed = "speed";  // float64, m/s along its path
inline constexpr const char* start = "start";  // float64, m: arc length at t = 0
inline constexpr const char* path = "path";    // string: the name of its path
}  // namespace pantograph_attribute

// ---- Root attributes. ----
namespace root_attribute {
inline constexpr const char* format = "format";                // string: transient_layout::format
inline constexpr const char* scene_text = "scene_text";        // string: the scene as run
inline constexpr const char* scene_file = "scene_file";        // string
inline constexpr const char* code_version = "code_version";    // string
inline constexpr const char* command_line = "command_line";    // string
inline constexpr const char* run_id = "run_id";                // string: 32 hex digits
inline constexpr const char* petsc_options = "petsc_options";  // string
inline constexpr const char* n_ranks = "n_ranks";              // int64
inline constexpr const char* n_dofs = "n_dofs";                // int64
inline constexpr const char* analysis = "analysis";            // string: analysis_dynamic
inline constexpr const char* status = "status";                // string: "running", then the end
inline constexpr const char* evaluation_start = "evaluation_start";  // float64, m
inline constexpr const char* evaluation_end = "evaluation_end";      // float64, m
// string: the acceptance ranges of the statistics ("en50318"); absent: none
inline constexpr const char* acceptance = "acceptance";
// float64, m: catenary.window only, how far along x the window moves each time
inline constexpr const char* window_shift_x = "window_shift_x";
// After the run, the work statistics (float64) the caller of TransientWriter::close names.
}  // namespace root_attribute
inline constexpr const char* analysis_dynamic = "dynamic";
inline constexpr const char* status_running = "running";

// Not collective. Throws catena::InputError naming `path` and the attribute `format`
// unless the open file `file` is a time series of this layout: its root attribute format
// is transient_layout::format. The message names the format found and the one expected;
// a time series written before the attribute existed (analysis = "dynamic", no format)
// is said to come from an older Catena, to be run again.
void require_transient_format(hid_t file, const std::string& path);

}  // namespace catena::io::transient_layout
