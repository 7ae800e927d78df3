#include "catena/model/model_summary.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <bit>
#include <cmath>
#include <map>
#include <vector>

#include "catena/model/element_kinds.hpp"
#include "catena/model/node_kinds.hpp"
#include "catena/model/path_stations.hpp"
#include "number_format.hpp"
#include "summary_table.hpp"

namespace catena::model {

std::string detail::plural(long long n, const std::string& word) {
  std::string text = std::to_string(n);
  text += ' ';
  text += word;
  if (n != 1) text += 's';
  return text;
}

namespace {

using detail::format_number;
using detail::format_vector;
using detail::plural;

// What acts on a revolute or prismatic joint's coordinate, for its row: "" if nothing.
std::string joint_forces(const Joint& j) {
  if (!j.has_coordinate_force()) return "";
  const bool revolute = j.type == JointType::revolute;
  const std::string torque = revolute ? " N*m" : " N", angle = revolute ? " rad" : " m";
  std::string text;
  auto add = [&](const std::string& part) { text += (text.empty() ? "; " : ", ") + part; };
  if (j.stiffness != 0.0)
    add("spring " + format_number(j.stiffness) + torque + (revolute ? "/rad" : "/m") + " about " +
        format_number(j.neutral) + angle);
  if (j.damping != 0.0)
    add("dashpot " + format_number(j.damping) + torque + (revolute ? "*s/rad" : "*s/m"));
  if (j.neutral_velocity != 0.0 || j.neutral_amplitude != 0.0)
    add("its neutral moving (a servo): " +
        (j.neutral_velocity != 0.0 ? format_number(j.neutral_velocity) + angle + "/s * t" : "") +
        (j.neutral_velocity != 0.0 && j.neutral_amplitude != 0.0 ? " + " : "") +
        (j.neutral_amplitude != 0.0 ? format_number(j.neutral_amplitude) + angle + " * sin(2 pi " +
                                          format_number(j.neutral_frequency) + " Hz * t)"
                                    : ""));
  if (j.actuator != 0.0) add("actuator " + format_number(j.actuator) + torque);
  if (j.limit > 0.0) add("limited to " + format_number(j.limit) + torque);
  if (j.friction > 0.0)
    add("dry friction " + format_number(j.friction) + torque + " (stick speed " +
        format_number(j.stick_speed) + angle + "/s)");
  return text;
}

// Counts per element kind in variant order, e.g. "cable 300, bar 12".
std::string kind_counts(const std::vector<long long>& counts) {
  std::string text;
  for (std::size_t k = 0; k < counts.size(); ++k)
    if (counts[k] > 0)
      text += (text.empty() ? "" : ", ") + std::string(element_kind_name_at(static_cast<int>(k))) +
              " " + std::to_string(counts[k]);
  return text.empty() ? "none" : text;
}

// What one set (a line name or an explicit elements' `set`) holds.
struct SetSummary {
  std::vector<long long> count_per_kind = std::vector<long long>(element_kind_count, 0);
  long long n_cables = 0;
  double min_prestrain = 0.0, max_prestrain = 0.0;
  double min_tension = 0.0, max_tension = 0.0;  // EA·prestrain, N (EA may differ)

  void add(const ElementDesc& element) {
    ++count_per_kind[element.props->index()];
    const auto* cable = std::get_if<CableProps>(&*element.props);
    if (!cable) return;
    const double tension = cable->EA * cable->prestrain;
    if (n_cables++ == 0) {
      min_prestrain = max_prestrain = cable->prestrain;
      min_tension = max_tension = tension;
      return;
    }
    min_prestrain = std::min(min_prestrain, cable->prestrain);
    max_prestrain = std::max(max_prestrain, cable->prestrain);
    min_tension = std::min(min_tension, tension);
    max_tension = std::max(max_tension, tension);
  }

  std::string text() const {
    long long total = 0;
    for (const long long c : count_per_kind) total += c;
    std::string out = plural(total, "element") + " (" + kind_counts(count_per_kind) + ")";
    if (n_cables == 0) return out;
    const auto range = [](double lo, double hi) {
      return lo == hi ? format_number(lo) : format_number(lo) + " to " + format_number(hi);
    };
    // EA·ε_p is the tension at the mesh length; a negative one means a slack cable
    // (longer unstretched than its mesh), not a compressed one.
    const std::string prestress =
        ", prestrain " + range(min_prestrain, max_prestrain) +
        " (tension at mesh length EA*prestrain = " + range(min_tension, max_tension) + " N";
    return out + prestress + (max_prestrain < 0.0 ? "; slack)" : ")");
  }
};

struct DofCounts {
  std::map<UnknownKind, long long> nodes_of_kind;
  long long total = 0;
  long long fixed = 0;
};

DofCounts count_dofs(const Model& model) {
  DofCounts c;
  for (const UnknownKind kind : node_kinds(model)) {
    ++c.nodes_of_kind[kind];
    c.total += kind_info(kind).size;
  }
  // A clamp holding a slope's direction removes two of its three components.
  for (const Support& s : model.supports)
    c.fixed += std::popcount(s.fixed_mask) + (s.slope_direction ? 2 : 0);
  return c;
}

}  // namespace

int suggested_rank_count(const Model& model) {
  const DofCounts dofs = count_dofs(model);
  const double ranks =
      std::round(static_cast<double>(dofs.total - dofs.fixed) / free_dofs_per_rank_target);
  return std::max(1, static_cast<int>(ranks));
}

std::vector<std::string> scene_warnings(const Model& model) {
  detail::SummaryTable unused;
  detail::SummaryNotes notes;
  if (model.catenary) detail::describe_catenary(model, unused, notes);
  detail::describe_moving(model, unused, notes);
  return notes.warnings;
}

std::string describe(const Model& model, int n_ranks_running) {
  detail::SummaryTable t;
  detail::SummaryNotes notes;
  t.heading("Scene" + (model.name.empty() ? std::string() : " '" + model.name + "'") +
            (model.source_file.empty() ? std::string() : " from " + model.source_file));

  std::vector<long long> per_kind(element_kind_count, 0);
  std::vector<std::string> set_order;
  std::map<std::string, SetSummary> sets;
  for (const ElementDesc& element : model.elements) {
    ++per_kind[element.props->index()];
    if (!sets.contains(element.set)) set_order.push_back(element.set);
    sets[element.set].add(element);
  }

  const DofCounts dofs = count_dofs(model);
  std::string dof_split;
  // Widest kinds first.
  for (auto it = dofs.nodes_of_kind.rbegin(); it != dofs.nodes_of_kind.rend(); ++it) {
    const UnknownKindInfo& kind = kind_info(it->first);
    dof_split += (dof_split.empty() ? "" : " + ") + std::to_string(it->second) + " " +
                 std::string(kind.label) + " nodes x " + std::to_string(kind.size);
  }

  Vec3 total_load = Vec3::Zero();
  for (const NodalLoad& load : model.nodal_loads) total_load += load.force;
  double total_mass = 0.0;
  for (const PointMass& m : model.point_masses) total_mass += m.mass;

  t.row("nodes", std::to_string(model.nodes.size()));
  t.row("elements", std::to_string(model.elements.size()) + " (" + kind_counts(per_kind) + ")");
  t.row("DOFs", std::to_string(dofs.total) + " = " + dof_split);
  t.row("fixed DOFs", std::to_string(dofs.fixed));
  t.row("free DOFs", std::to_string(dofs.total - dofs.fixed));
  t.row("supports", std::to_string(model.supports.size()));
  t.row("elastic supports", std::to_string(model.elastic_supports.size()));
  if (!model.absorbing_ends.empty())
    t.row("absorbing ends",
          std::to_string(model.absorbing_ends.size()) +
              " (held in statics; in the run pulled by their initial force, with dashpots "
              "matched to the line's wave impedances)");
  if (!model.constraints.empty()) {
    int by_type[8] = {0, 0, 0, 0, 0, 0, 0, 0};
    for (const Constraint& c : model.constraints) ++by_type[static_cast<int>(c.type)];
    const int frames = by_type[static_cast<int>(ConstraintType::frame_lengths)] +
                       by_type[static_cast<int>(ConstraintType::frame_angles)];
    t.row("constraints",
          std::to_string(model.constraints.size()) + " (coincident " + std::to_string(by_type[0]) +
              ", pinned " + std::to_string(by_type[1]) + ", prescribed " +
              std::to_string(by_type[2]) +
              (frames > 0 ? ", rigid-body frames " + std::to_string(frames) : "") +
              (model.joints.empty() ? "" : ", joints " + std::to_string(model.joints.size())) +
              (model.sliders.empty() ? "" : ", sliders " + std::to_string(model.sliders.size())) +
              (by_type[7] == 0 ? "" : ", bilateral contacts " + std::to_string(by_type[7])) +
              "): " + std::to_string(total_multipliers(model)) + " Lagrange multipliers");
  }
  for (const RigidBody& b : model.rigid_bodies) {
    const model::Node& node = model.nodes[static_cast<size_t>(b.node)];
    const Eigen::SelfAdjointEigenSolver<Mat3> principal(b.inertia);
    t.row("rigid body '" + b.name + "'",
          "node " + std::to_string(node.id) + ", mass " + format_number(b.mass) +
              " kg, centre of mass " +
              format_vector(node.position + b.centre_of_mass[0] * node.tangent +
                            b.centre_of_mass[1] * node.section_y +
                            b.centre_of_mass[2] * node.section_z) +
              " m, principal moments " + format_vector(principal.eigenvalues()) +
              " kg*m^2; natural coordinates (r, e1, e2, e3: 12 unknowns; 2 frame constraints, 6 "
              "multipliers)");
  }
  static const char* joint_types[] = {"spherical", "revolute", "cylindrical", "prismatic", "fixed"};
  for (const Joint& j : model.joints) {
    const std::string other =
        j.body_b >= 0   ? "body '" + model.rigid_bodies[static_cast<size_t>(j.body_b)].name + "'"
        : j.node_b >= 0 ? "node " + std::to_string(model.nodes[static_cast<size_t>(j.node_b)].id)
                        : std::string("ground");
    const bool has_axis = j.type == JointType::revolute || j.type == JointType::cylindrical ||
                          j.type == JointType::prismatic;
    t.row("joint '" + j.name + "'",
          std::string(joint_types[static_cast<int>(j.type)]) + " between body '" +
              model.rigid_bodies[static_cast<size_t>(j.body_a)].name + "' and " + other + " at " +
              format_vector(j.point) + " m" + (has_axis ? ", axis " + format_vector(j.axis) : "") +
              ": " + std::to_string(joint_equations(j)) + " multipliers" + joint_forces(j));
  }
  for (const Slider& slider : model.sliders) {
    const ElementPath& path = model.paths[static_cast<size_t>(slider.path)];
    t.row("slider '" + slider.name + "'",
          "node " + std::to_string(model.nodes[static_cast<size_t>(slider.node)].id) + " along '" +
              path.name + "' (" + std::to_string(path.elements.size()) + " elements, " +
              format_number(path_stations(model, path.elements).length()) + " m), from " +
              format_number(slider.start) + " m, damping " + format_number(slider.damping) +
              " N*s/m" +
              (slider.friction > 0.0
                   ? ", Coulomb friction " + format_number(slider.friction) + " (stick speed " +
                         format_number(slider.stick_speed) + " m/s)"
                   : std::string()) +
              "; unknowns x, y, z, s: 3 multipliers");
  }
  for (const Surface& s : model.surfaces)
    t.row("surface '" + s.name + "'",
          "plane through " + format_vector(s.point) + " m, normal " + format_vector(s.normal) +
              ", " + plural(static_cast<long long>(s.nodes.size()), "node") +
              " may touch it: " + "stiffness " + format_number(s.stiffness) + " N/m, damping " +
              format_number(s.damping) + " N*s/m" +
              (s.friction > 0.0 ? ", Coulomb friction " + format_number(s.friction) +
                                      " (stick speed " + format_number(s.stick_speed) + " m/s)"
                                : std::string()));
  t.row("nodal loads",
        std::to_string(model.nodal_loads.size()) + " (sum " + format_vector(total_load) + " N)");
  t.row("point masses",
        std::to_string(model.point_masses.size()) + " (sum " + format_number(total_mass) + " kg)");
  t.row("gravity", format_vector(model.gravity) + " m/s^2");
  if (model.catenary) {
    detail::describe_catenary(model, t, notes);
    t.row("shape finding",
          "dropper lengths, steady-arm preloads and wire prestrains are set by 'catena run' "
          "before the analysis (docs/catenary.md)");
    if (model.evaluation_end > model.evaluation_start)
      t.row("evaluation", "contact wire from " + format_number(model.evaluation_start) + " m to " +
                              format_number(model.evaluation_end) + " m" +
                              (model.acceptance == "en50318"
                                   ? "; the EN 50318 reference case: catena stats checks the "
                                     "statistics at 250 and 300 km/h against its ranges"
                                   : ""));
  }
  detail::describe_moving(model, t, notes);
  if (model.analysis == AnalysisType::dynamic && !detail::structure_is_damped(model))
    notes.left_out.push_back(
        model.catenary
            ? "no structural damping: nothing damps the wires (no damping_time or rayleigh "
              "on either wire, dropper, steady-arm and messenger-support damping 0); only the "
              "integrator's numerical dissipation acts"
            : "no structural damping: no element or elastic support outside the pantographs "
              "has damping; only the integrator's numerical dissipation acts");
  if (!set_order.empty()) {
    t.heading("  sets");
    for (const std::string& name : set_order)
      t.row(name.empty() ? "(no set)" : name, sets.at(name).text(), 4);
  }
  const StaticOptions& s = model.static_options;
  if (model.analysis == AnalysisType::dynamic) {
    const IntegratorOptions& i = model.dynamic_options.integrator;
    // Appended piece by piece: GCC 12's -Wrestrict misfires on `" " + std::to_string(n)`.
    std::string method = i.type;
    if (i.type == "hht") {
      method += " alpha ";
      method += format_number(i.alpha);
    } else if (i.type == "bdf" || i.type == "abm") {
      method += " order ";
      method += std::to_string(i.order);
    } else if (i.type != "petsc" && i.type != "central_difference" && i.type != "park" &&
               i.type != "rattle") {
      method += ' ';
      method += std::to_string(i.stages);
      method += " stages";
    }
    std::string text = "duration ";
    text += format_number(model.dynamic_options.duration);
    text += " s, ";
    text += method;
    text += ", dt ";
    text += format_number(i.dt);
    text += " s";
    if (i.adaptive) {
      text += " (adaptive, rtol ";
      text += format_number(i.rtol);
      text += ')';
    }
    t.row("dynamics", text);
    t.row("initial state", model.dynamic_options.initial.from_static ? "static equilibrium (below)"
                                                                     : "reference configuration");
    t.row("structure",
          model.dynamic_options.structure == StructureModel::modal
              ? "modal: the structure linearised about the initial static equilibrium, the "
                "catenary in its modes below " +
                    format_number(model.dynamic_options.modal_cutoff) +
                    " Hz (analysis.modal_cutoff; higher modes and large motions left out), "
                    "the pantographs in their own DOFs; contact and slack droppers nonlinear "
                    "(as forces at their points)" +
                    (model.dynamic_options.modal_basis.empty()
                         ? std::string()
                         : "; modes from " + model.dynamic_options.modal_basis +
                               " when it holds this structure's, else computed and written "
                               "there (analysis.modal_basis)")
          : model.dynamic_options.structure == StructureModel::linear
              ? "linear: cables and beams linearised about the initial static equilibrium "
                "(constant stiffness and damping; large motions and the stiffness the "
                "tension changes with them left out); bars, springs, masses, tension-only "
                "cables and contacts nonlinear"
              : "nonlinear (analysis.structure: linear linearises the cables and beams, "
                "modal keeps the catenary's modes below a cut-off)");
  }
  t.row("analysis", std::string(model.analysis == AnalysisType::dynamic ? "initial " : "") +
                        "static; load steps initial " + format_number(s.initial_load_step) +
                        ", min " + format_number(s.min_load_step) + ", at most " +
                        std::to_string(s.max_load_steps) + "; Newton rtol " +
                        format_number(s.rtol) + ", atol " + format_number(s.atol) + " N, at most " +
                        std::to_string(s.max_newton_iterations) + " iterations");
  t.row("output", model.output.file);
  t.row("suggested ranks", std::to_string(suggested_rank_count(model)) + " (about " +
                               std::to_string(free_dofs_per_rank_target) +
                               " free DOFs per rank); this check ran on " +
                               plural(n_ranks_running, "rank"));
  if (!notes.left_out.empty()) {
    t.heading("Left out:");
    for (const std::string& item : notes.left_out) t.heading("  - " + item);
  }
  detail::advise_structure(model, t);
  for (const std::string& warning : notes.warnings) t.heading("warning: " + warning);
  return t.str();
}

}  // namespace catena::model
