#include "catena/catenary/shape_finding.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "catena/core/error.hpp"
#include "catenary_subproblems.hpp"
#include "static_snapshot.hpp"

namespace catena::catenary {
namespace {

using model::BarProps;
using model::CableProps;
using model::CatenaryLayout;

// What shape finding adjusts, applied to the model before every solve.
struct Unknowns {
  std::vector<double> lengths;   // m, per dropper
  std::vector<double> preloads;  // N, per registration (0 where not held)
  double contact_prestrain = 0.0;
  double messenger_prestrain = 0.0;
  std::vector<double> stitch_prestrains;  // per stitch wire
};

void set_wire_prestrain(model::Model& m, const model::CatenaryWire& wire, double prestrain) {
  model::edit_shared(m.elements, wire.elements, [prestrain](model::ElementProps& p) {
    std::get<CableProps>(p).prestrain = prestrain;
  });
}

// A cable dropper's chain (top to bottom) given the unstretched length l0: prestrain
// L/l0 − 1 (L its mesh length), EA = stiffness·l0 when the stiffness is the design value,
// and the Kelvin–Voigt time that keeps its damping c = EA·τ/l0 (N·s/m) as built.
void set_cable_dropper_length(model::Model& m, const model::CatenaryDropper& d, double l0) {
  model::edit_shared(m.elements, d.elements, [&d, l0](model::ElementProps& p) {
    auto& cable = std::get<CableProps>(p);
    const double damping = cable.EA * cable.damping_time * (1.0 + cable.prestrain) / d.mesh_length;
    if (d.stiffness > 0.0) cable.EA = d.stiffness * l0;
    cable.prestrain = d.mesh_length / l0 - 1.0;
    cable.damping_time = damping * l0 / cable.EA;
  });
}

void apply(const Unknowns& u, model::Model& m) {
  CatenaryLayout& layout = *m.catenary;
  for (std::size_t i = 0; i < layout.droppers.size(); ++i) {
    model::CatenaryDropper& d = layout.droppers[i];
    d.unstretched_length = u.lengths[i];
    model::SharedProps& props = m.elements[static_cast<std::size_t>(d.element)].props;
    if (std::holds_alternative<BarProps>(*props)) {
      auto* bar = &std::get<BarProps>(props.edit());
      bar->unstretched_length = u.lengths[i];
      if (d.stiffness > 0.0) bar->EA = d.stiffness * u.lengths[i];
    } else {
      set_cable_dropper_length(m, d, u.lengths[i]);
    }
  }
  for (std::size_t j = 0; j < layout.registrations.size(); ++j) {
    const model::CatenaryRegistration& r = layout.registrations[j];
    if (r.load >= 0)
      m.nodal_loads[static_cast<std::size_t>(r.load)].force = Vec3(0, 0, u.preloads[j]);
  }
  set_wire_prestrain(m, layout.contact_wire, u.contact_prestrain);
  set_wire_prestrain(m, layout.messenger, u.messenger_prestrain);
  for (std::size_t k = 0; k < layout.stitch_wires.size(); ++k)
    set_wire_prestrain(m, layout.stitch_wires[k].wire, u.stitch_prestrains[k]);
}

double wire_EA(const model::Model& m, const model::CatenaryWire& wire) {
  return std::get<CableProps>(*m.elements[static_cast<std::size_t>(wire.elements.front())].props)
      .EA;
}

// A dropper's section, bar or cable: EA (N) and mass per unstretched length (kg/m).
struct DropperSection {
  double EA = 0.0, mass_per_length = 0.0;
};

DropperSection dropper_section(const model::Model& m, const model::CatenaryDropper& d) {
  const auto& props = *m.elements[static_cast<std::size_t>(d.element)].props;
  if (const auto* bar = std::get_if<BarProps>(&props)) return {bar->EA, bar->mass_per_length};
  const auto& cable = std::get<CableProps>(props);
  return {cable.EA, cable.mass_per_length};
}

// EA of dropper i when its unstretched length is l0.
double dropper_EA(const model::Model& m, const model::CatenaryDropper& d, double l0) {
  return d.stiffness > 0.0 ? d.stiffness * l0 : dropper_section(m, d).EA;
}

// Half a dropper's weight (N): what a bar lumps on each of its nodes, and what a vertical
// cable dropper's weight puts on each end.
double half_weight(const model::Model& m, const model::CatenaryDropper& d, double l0) {
  return 0.5 * dropper_section(m, d).mass_per_length * l0 * m.gravity.norm();
}

std::string describe_dropper(const model::Model& m, std::size_t i) {
  const model::CatenaryDropper& d = m.catenary->droppers[i];
  const Vec3& x = m.nodes[static_cast<std::size_t>(d.contact_node)].position;
  char text[160];
  std::snprintf(text, sizeof text, "dropper %zu (span %d, x = %.4g m, contact-wire node %lld)",
                i + 1, d.span + 1, x.x(),
                static_cast<long long>(m.nodes[static_cast<std::size_t>(d.contact_node)].id));
  return text;
}

// The contact wire's local vertical stiffness at each of `nodes` (N/m): its tension over
// the distances to the neighbouring held points (droppers, supports), as for a taut string
// held at those points.
std::vector<double> local_contact_stiffness(const model::Model& m, const std::vector<int>& nodes) {
  const CatenaryLayout& layout = *m.catenary;
  std::vector<double> held_x{layout.support_x.front(), layout.support_x.back()};
  for (const model::CatenaryDropper& d : layout.droppers)
    held_x.push_back(m.nodes[static_cast<std::size_t>(d.contact_node)].position.x());
  for (const double x : layout.support_x) held_x.push_back(x);
  std::sort(held_x.begin(), held_x.end());
  held_x.erase(std::unique(held_x.begin(), held_x.end()), held_x.end());
  std::vector<double> k;
  for (const int node : nodes) {
    const double x = m.nodes[static_cast<std::size_t>(node)].position.x();
    const auto at = std::lower_bound(held_x.begin(), held_x.end(), x - 1e-9);
    const double left = at == held_x.begin() ? 0.0 : x - *(at - 1);
    const double right = at + 1 == held_x.end() ? 0.0 : *(at + 1) - x;
    k.push_back(layout.contact_wire.tension *
                ((left > 0.0 ? 1.0 / left : 0.0) + (right > 0.0 ? 1.0 / right : 0.0)));
  }
  return k;
}

// The decoupled estimate (catenary_subproblems.hpp).
// `lengths`: the droppers' lengths that set their weight (N lumped per end).
Unknowns estimate_once(MPI_Comm comm, const model::Model& m, const ShapeFindingOptions& o,
                       const std::vector<double>& lengths, ShapeFindingReport& report) {
  const CatenaryLayout& layout = *m.catenary;
  const std::size_t n = layout.droppers.size();
  std::vector<double> weight(n);
  for (std::size_t i = 0; i < n; ++i) weight[i] = half_weight(m, layout.droppers[i], lengths[i]);
  const detail::ContactWireLoads loads =
      detail::solve_contact_wire_held(comm, m, weight, o.tension_rtol);
  const detail::MessengerShape messenger =
      detail::solve_messenger_loaded(comm, m, loads.dropper_force, weight, o.tension_rtol);
  report.n_static_solves += loads.n_solves + messenger.n_solves;

  Unknowns u;
  for (std::size_t i = 0; i < n; ++i) {
    const model::CatenaryDropper& d = layout.droppers[i];
    Vec3 bottom = m.nodes[static_cast<std::size_t>(d.contact_node)].position;
    bottom.z() = d.design_z;
    const double gap = (messenger.dropper_top[i] - bottom).norm();
    const double force = loads.dropper_force[i];
    const double length =
        d.stiffness > 0.0 ? gap - force / d.stiffness : gap / (1.0 + force / dropper_EA(m, d, gap));
    if (!(length > 0.0) || messenger.dropper_top[i].z() <= d.design_z)
      throw NumericalError("shape finding: " + describe_dropper(m, i) +
                           " would need a non-positive length: " +
                           (d.stitch < 0 ? "the messenger" : "its stitch wire") +
                           ", loaded by the contact wire, hangs to z = " +
                           std::to_string(messenger.dropper_top[i].z()) +
                           " m, at or below the contact wire's design height " +
                           std::to_string(d.design_z) + " m. Raise catenary.system_height or the " +
                           (d.stitch < 0 ? "messenger's tension." : "stitch wires' tension."));
    u.lengths.push_back(length);
  }
  u.preloads = loads.registration_force;
  u.contact_prestrain = layout.contact_wire.tension / wire_EA(m, layout.contact_wire);
  u.messenger_prestrain = messenger.prestrain;
  u.stitch_prestrains = messenger.stitch_prestrains;
  return u;
}

// Step 1. A dropper's weight depends on its length: with massive droppers the estimate is
// made twice, the second time with the first one's lengths.
Unknowns initial_estimate(MPI_Comm comm, const model::Model& m, const ShapeFindingOptions& o,
                          ShapeFindingReport& report) {
  const CatenaryLayout& layout = *m.catenary;
  const std::vector<double> mesh_lengths(layout.droppers.size(), layout.system_height);
  Unknowns u = estimate_once(comm, m, o, mesh_lengths, report);
  const bool massive =
      std::any_of(layout.droppers.begin(), layout.droppers.end(),
                  [&](const model::CatenaryDropper& d) { return half_weight(m, d, 1.0) > 0.0; });
  if (massive) u = estimate_once(comm, m, o, u.lengths, report);
  return u;
}

struct Errors {
  std::vector<double> dropper, registration;  // m, z − z_design
  double max = 0.0;
  std::size_t worst = 0;  // dropper index of the largest dropper error
  double contact_tension = 0.0, messenger_tension = 0.0;
  std::vector<double> stitch_tensions;  // N, mean axial force per stitch wire
};

Errors measure(const model::Model& m, const detail::StaticSnapshot& s) {
  const CatenaryLayout& layout = *m.catenary;
  Errors e;
  double worst_dropper = -1.0;
  for (std::size_t i = 0; i < layout.droppers.size(); ++i) {
    const model::CatenaryDropper& d = layout.droppers[i];
    e.dropper.push_back(s.positions[static_cast<std::size_t>(d.contact_node)].z() - d.design_z);
    if (std::abs(e.dropper.back()) > worst_dropper) {
      worst_dropper = std::abs(e.dropper.back());
      e.worst = i;
    }
  }
  e.max = std::max(worst_dropper, 0.0);
  for (const model::CatenaryRegistration& r : layout.registrations) {
    const double error =
        r.load >= 0 ? s.positions[static_cast<std::size_t>(r.node)].z() - r.design_z : 0.0;
    e.registration.push_back(error);
    e.max = std::max(e.max, std::abs(error));
  }
  e.contact_tension = detail::mean_axial_force(m, s, layout.contact_wire.elements);
  e.messenger_tension = detail::mean_axial_force(m, s, layout.messenger.elements);
  for (const model::CatenaryStitch& stitch : layout.stitch_wires)
    e.stitch_tensions.push_back(detail::mean_axial_force(m, s, stitch.wire.elements));
  return e;
}

bool tension_off(double mean, double tension, double rtol) {
  return std::abs(mean - tension) > rtol * tension;
}

bool tensions_converged(const CatenaryLayout& layout, const Errors& e, double rtol) {
  bool converged = !tension_off(e.contact_tension, layout.contact_wire.tension, rtol) &&
                   !tension_off(e.messenger_tension, layout.messenger.tension, rtol);
  for (std::size_t k = 0; k < layout.stitch_wires.size(); ++k)
    converged =
        converged && !tension_off(e.stitch_tensions[k], layout.stitch_wires[k].wire.tension, rtol);
  return converged;
}

// A window (model::CatenaryWindow) stands for a line that repeats span after span, but its
// shape was found with its ends anchored, where the spans hang otherwise (the end supports
// are rigid, the others elastic: the first and last spans' droppers come out up to 4 %
// longer on EN 50318's line). Every span takes the middle span's droppers, and every
// steady arm and stitch wire the middle one's values, so that the state can move from span
// to span as the window moves.
void repeat_middle_span(const CatenaryLayout& layout, Unknowns& u) {
  const auto spans = static_cast<std::size_t>(layout.window->spans);
  const std::size_t per_span = u.lengths.size() / spans, middle = spans / 2;
  for (std::size_t i = 0; i < u.lengths.size(); ++i)
    u.lengths[i] = u.lengths[middle * per_span + i % per_span];
  // One per intermediate support each.
  const auto repeat = [](std::vector<double>& values) {
    if (!values.empty()) values.assign(values.size(), values[values.size() / 2]);
  };
  repeat(u.preloads);
  repeat(u.stitch_prestrains);
}

// The iteration on `model`, which ends with the unknowns found applied to it.
ShapeFindingReport find_shape(MPI_Comm comm, model::Model& model,
                              const ShapeFindingOptions& options, Unknowns& found) {
  CATENA_ASSERT(model.catenary.has_value(), "shape finding needs a catenary layout");
  const CatenaryLayout layout = *model.catenary;
  const std::size_t n = layout.droppers.size();
  ShapeFindingReport report;
  Unknowns u = initial_estimate(comm, model, options, report);

  std::vector<int> registration_nodes;
  for (const model::CatenaryRegistration& r : layout.registrations)
    registration_nodes.push_back(r.node);
  const std::vector<double> k_registration = local_contact_stiffness(model, registration_nodes);
  const double EA_contact = wire_EA(model, layout.contact_wire);
  const double EA_messenger = wire_EA(model, layout.messenger);

  double relaxation = 1.0;  // halved when the error grows
  Errors e;
  detail::StaticSnapshot snapshot;
  for (int iteration = 1;; ++iteration) {
    apply(u, model);
    snapshot = detail::solve_static_snapshot(comm, model);
    ++report.n_static_solves;
    report.n_iterations = iteration;
    const double previous_max = report.error_history.empty() ? 0.0 : report.error_history.back();
    e = measure(model, snapshot);
    report.error_history.push_back(e.max);
    if (options.on_iteration) options.on_iteration(iteration, e.max);
    if (e.max < options.height_tolerance && tensions_converged(layout, e, options.tension_rtol))
      break;
    if (iteration >= options.max_iterations) {
      char text[200];
      std::snprintf(text, sizeof text,
                    " is %.3g mm after %d iterations (tolerance %.3g mm); wire tensions "
                    "%.6g N and %.6g N (design %.6g N and %.6g N)",
                    1e3 * e.max, iteration, 1e3 * options.height_tolerance, e.contact_tension,
                    e.messenger_tension, layout.contact_wire.tension, layout.messenger.tension);
      std::string stitch;
      for (std::size_t k = 0; k < layout.stitch_wires.size(); ++k) {
        char one[80];
        std::snprintf(one, sizeof one, "%s%.6g N", k == 0 ? "; stitch wires " : ", ",
                      e.stitch_tensions[k]);
        stitch += one;
      }
      if (!layout.stitch_wires.empty())
        stitch += " (design " + std::to_string(layout.stitch_wires.front().wire.tension) + " N)";
      throw NumericalError("shape finding did not converge: the largest height error (at " +
                           describe_dropper(model, e.worst) + " or a registration)" + text +
                           stitch + ".");
    }
    if (iteration > 1 && e.max > previous_max) relaxation *= 0.5;

    // Gain 1 on the lengths: a dropper lengthened by δ lowers the contact wire by δ/g with
    // g between 1 (all droppers together: the forces, and so the messenger, stay) and
    // 1 + T_c/T_m + k_c/k_d ≈ 2.3 (one dropper: the messenger moves too), so the error
    // contracts by 1 − 1/g in [0, 0.6) for every pattern. A local-stiffness gain g would
    // overshoot the first by g and diverge. The preload gain is a quarter of the wire's
    // local stiffness for the same reason: the neighbouring droppers give way.
    for (std::size_t i = 0; i < n; ++i)
      u.lengths[i] = std::max(u.lengths[i] + relaxation * e.dropper[i], 0.5 * u.lengths[i]);
    for (std::size_t j = 0; j < layout.registrations.size(); ++j)
      if (layout.registrations[j].load >= 0)
        u.preloads[j] -= relaxation *
                         (layout.registrations[j].stiffness + 0.25 * k_registration[j]) *
                         e.registration[j];
    // Only a wire whose tension is off is corrected: a correction moves the messenger and
    // with it every dropper's error.
    const double rtol = options.tension_rtol;
    if (tension_off(e.contact_tension, layout.contact_wire.tension, rtol))
      u.contact_prestrain = detail::corrected_prestrain(u.contact_prestrain, e.contact_tension,
                                                        layout.contact_wire.tension, EA_contact);
    if (tension_off(e.messenger_tension, layout.messenger.tension, rtol))
      u.messenger_prestrain = detail::corrected_prestrain(
          u.messenger_prestrain, e.messenger_tension, layout.messenger.tension, EA_messenger);
    // A stitch wire's sag strain is measured from its shape (catenary_subproblems.hpp).
    for (std::size_t k = 0; k < layout.stitch_wires.size(); ++k) {
      const model::CatenaryWire& wire = layout.stitch_wires[k].wire;
      if (tension_off(e.stitch_tensions[k], wire.tension, rtol))
        u.stitch_prestrains[k] = detail::corrected_prestrain(
            u.stitch_prestrains[k], e.stitch_tensions[k], wire.tension, wire_EA(model, wire),
            detail::sag_strain(model, snapshot, wire.elements));
    }
  }

  found = u;
  report.dropper_lengths = u.lengths;
  report.registration_preloads = u.preloads;
  report.height_errors = e.dropper;
  report.registration_errors = e.registration;
  report.max_height_error = e.max;
  report.contact_wire_tension = e.contact_tension;
  report.messenger_tension = e.messenger_tension;
  report.stitch_tensions = e.stitch_tensions;
  for (const model::CatenaryDropper& d : layout.droppers)
    report.dropper_forces.push_back(snapshot.axial_force[static_cast<std::size_t>(d.element)]);
  return report;
}

}  // namespace

ShapeFindingReport find_catenary_shape(MPI_Comm comm, model::Model& model,
                                       const ShapeFindingOptions& options) {
  CATENA_ASSERT(model.catenary.has_value(), "shape finding needs a catenary layout");
  // The design shape is the catenary's own, without the pantographs pressing on it (a head
  // standing in a span would lift the wire there, and shape finding would shorten that
  // span's droppers to pull it back down) and without moving loads. The pantographs'
  // stages stay in the copy, held by their ground springs, touching nothing; a mechanism
  // pantograph's arm is held where the scene draws it (its air spring, with nothing
  // to push against, would throw the arm up): the height of the arm's centre of mass fixes
  // its angle (holding more would repeat the joints' conditions), and the head stays on its
  // suspension.
  model::Model bare = model;
  for (const model::MovingContact& c : bare.contacts)
    if (c.mechanism) bare.supports.push_back({c.mechanism_nodes.back(), 0b100u, false, 0u});
  bare.contacts.clear();
  bare.moving_loads.clear();
  Unknowns found;
  ShapeFindingReport report = find_shape(comm, bare, options, found);
  if (model.catenary->window) {
    repeat_middle_span(*model.catenary, found);
    report.dropper_lengths = found.lengths;  // as the run uses them
    report.registration_preloads = found.preloads;
  }
  apply(found, model);
  return report;
}

}  // namespace catena::catenary
