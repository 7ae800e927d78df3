#include "dynamics_reader.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "catena/model/integrator_catalogue.hpp"
#include "did_you_mean.hpp"
#include "number_format.hpp"

namespace catena::model::detail {
namespace {

void fail_if_present(const Field& f, const std::string& why) {
  if (f.present()) f.fail(why);
}

// What the integrator types are and which keys apply to each: model/integrator_catalogue.hpp,
// which the solvers ask too. `constraints`: the scene's Lagrange-multiplier constraints.
void read_integrator(const Field& in, std::size_t constraints, bool nonlinear_constraints,
                     IntegratorOptions& o) {
  if (!in.present()) return;
  in.expect_map("integrator settings {type, stages, alpha, dt, adaptive, ...}");
  in.check_keys({"type", "stages", "alpha", "dt", "adaptive", "rtol", "atol", "dt_min", "dt_max",
                 "error_estimate", "newton", "newton_rtol", "newton_atol", "max_newton_iterations",
                 "linear_algebra", "local_newton", "tangent_every", "order"});
  const Field type = in.child("type");
  o.type = type.text_or(o.type);
  const IntegratorType* facts = find_integrator_type(o.type);
  if (!facts) {
    std::vector<std::string> names;
    for (const IntegratorType& t : integrator_types()) {
      names.emplace_back(t.name);
      if (!t.alias.empty()) names.emplace_back(t.alias);
    }
    type.fail("unknown integrator type '" + o.type + "';" + did_you_mean(o.type, names) +
              " accepted: " + integrator_type_list());
  }
  o.type = facts->name;  // canonical: "radau" is stored as "radau_iia"
  const bool family = facts->method == IntegratorMethod::irk;
  const std::string irk_names = integrator_names(IntegratorMethod::irk);
  const Field stages = in.child("stages");
  if (family) {
    o.stages = static_cast<int>(stages.integer_or(
        default_stages(*facts, o.stages), IntRange::between(facts->min_stages, facts->max_stages)));
  } else {
    fail_if_present(stages, "'stages' applies to the implicit Runge-Kutta types (" + irk_names +
                                "), not to " + o.type);
  }
  const Field order = in.child("order");
  if (facts->max_order > 0)
    o.order = static_cast<int>(order.integer_or(o.order, IntRange::between(1, facts->max_order)));
  else
    fail_if_present(order,
                    "'order' applies to integrator types bdf and abm only (park is of "
                    "order 2; the Runge-Kutta types take 'stages')");
  const Field alpha = in.child("alpha");
  // petsc: HHT's alpha mapped onto -ts_type alpha2 (ignored by the other TS types).
  if (facts->takes_alpha)
    o.alpha = alpha.real_or(o.alpha, RealRange::between(-1.0 / 3.0, true, 0.0, true, ""));
  else
    fail_if_present(alpha,
                    "'alpha' applies to integrator type hht only (and petsc, for "
                    "-ts_type alpha2)");
  o.dt = in.child("dt").real_or(o.dt, RealRange::positive("s"));
  o.adaptive = in.child("adaptive").boolean_or(o.adaptive);
  const char* only_adaptive = " only applies with adaptive: true";
  for (const char* key : {"rtol", "atol", "dt_min", "dt_max", "error_estimate"})
    if (!o.adaptive) fail_if_present(in.child(key), std::string("'") + key + "'" + only_adaptive);
  o.rtol = in.child("rtol").real_or(o.rtol, RealRange::between(0.0, false, 1.0, false, ""));
  o.atol = in.child("atol").real_or(o.atol, RealRange::positive("m"));
  const Field dt_min = in.child("dt_min"), dt_max = in.child("dt_max");
  o.dt_min = dt_min.real_or(o.dt_min, RealRange::positive("s"));
  o.dt_max = dt_max.real_or(o.dt_max, RealRange::non_negative("s"));
  // A fixed step at or below the smallest step any run takes (dt_min, whose default a
  // fixed-step run keeps) was refused only after the static solve, as a numerical failure.
  if (!o.adaptive && o.dt <= o.dt_min)
    in.child("dt").fail("dt = " + format_number(o.dt) +
                        " s is not above the smallest step a run takes, " +
                        format_number(o.dt_min) + " s; accepted: a step above it");
  if (o.adaptive && o.dt_min >= o.dt)
    (dt_min.present() ? dt_min : in.child("dt"))
        .fail("dt_min = " + format_number(o.dt_min) +
              " s must be below the first step dt = " + format_number(o.dt) + " s");
  if (o.dt_max > 0.0 && o.dt_max < o.dt)
    dt_max.fail("dt_max = " + format_number(o.dt_max) + " s is below the first step dt = " +
                format_number(o.dt) + " s; expected 0 (no limit) or >= dt");
  const Field estimate = in.child("error_estimate");
  o.error_estimate = estimate.text_or(o.error_estimate);
  static const std::vector<std::string> estimates{"auto", "embedded", "step_doubling"};
  if (std::find(estimates.begin(), estimates.end(), o.error_estimate) == estimates.end())
    estimate.fail("unknown error estimate '" + o.error_estimate + "';" +
                  did_you_mean(o.error_estimate, estimates) +
                  " accepted: auto, embedded, step_doubling");
  const Field newton = in.child("newton");
  if (facts->takes_newton) {
    o.newton = newton.text_or(o.newton);
    const bool hht = facts->takes_linearly_implicit;
    if (o.newton != "simplified" && o.newton != "full" && !(hht && o.newton == "linearly_implicit"))
      newton.fail("unknown Newton variant '" + o.newton + "' for " + o.type + "; accepted: " +
                  (hht ? "simplified, full, linearly_implicit" : "simplified, full"));
    if (o.newton == "linearly_implicit" && constraints > 0)
      newton.fail(
          "newton: linearly_implicit takes no constraints (its linear model of the force "
          "leaves the multipliers' rows undefined); this scene has " +
          std::to_string(constraints) + "; use simplified or full");
  } else {
    fail_if_present(newton,
                    "'newton' applies to hht, central_difference, rattle, bdf, park and "
                    "the implicit Runge-Kutta types");
  }
  const Field tangent_every = in.child("tangent_every");
  if (o.newton == "linearly_implicit")
    o.tangent_every = static_cast<int>(
        tangent_every.integer_or(o.tangent_every, IntRange::between(0, 1000000000)));
  else
    fail_if_present(tangent_every, "'tangent_every' applies to newton: linearly_implicit only");
  const Field local_newton = in.child("local_newton");
  if (facts->takes_local_newton && o.newton == "linearly_implicit")
    fail_if_present(local_newton,
                    "'local_newton' does not apply to newton: linearly_implicit (one Newton "
                    "step per time step, never corrected)");
  else if (facts->takes_local_newton)
    o.local_newton = local_newton.boolean_or(o.local_newton);
  else
    fail_if_present(local_newton, "'local_newton' applies to hht only");
  const Field linear_algebra = in.child("linear_algebra");
  if (family) {
    o.linear_algebra = linear_algebra.text_or(o.linear_algebra);
    static const std::vector<std::string> choices{"auto", "decoupled", "coupled"};
    if (std::find(choices.begin(), choices.end(), o.linear_algebra) == choices.end())
      linear_algebra.fail("unknown stage linear algebra '" + o.linear_algebra + "';" +
                          did_you_mean(o.linear_algebra, choices) +
                          " accepted: auto, decoupled, coupled");
  } else {
    fail_if_present(linear_algebra, "'linear_algebra' applies to the implicit Runge-Kutta types (" +
                                        irk_names + "), not to " + o.type);
  }
  // abm is explicit: no Newton iteration for these to set.
  if (facts->name == "abm")
    for (const char* key : {"newton_rtol", "newton_atol", "max_newton_iterations"})
      fail_if_present(in.child(key), std::string("'") + key +
                                         "' does not apply to abm (explicit: no Newton iteration)");
  o.newton_rtol = in.child("newton_rtol")
                      .real_or(o.newton_rtol, RealRange::between(0.0, false, 1e-3, true, ""));
  o.newton_atol = in.child("newton_atol").real_or(o.newton_atol, RealRange::positive("N"));
  o.max_newton_iterations =
      static_cast<int>(in.child("max_newton_iterations")
                           .integer_or(o.max_newton_iterations, IntRange::between(1, 1000)));
  // The combinations the solvers refuse (constraints, the embedded estimate, the decoupled
  // solve), here where the message can name the line.
  if (const std::optional<IntegratorRefusal> refusal =
          refuse_integrator(o, constraints, nonlinear_constraints)) {
    const Field key = in.child(refusal->key);
    (key.present() ? key : in).fail(refusal->why);
  }
}

// Nodes of the line named `name` from its `from` to its `to` node (empty if none).
std::vector<int> line_nodes(const Model& model, const std::string& name) {
  std::vector<int> nodes;
  for (const ElementDesc& e : model.elements) {
    if (e.set != name) continue;
    if (nodes.empty()) nodes.push_back(e.nodes.front());
    nodes.push_back(e.nodes.back());
  }
  return nodes;
}

std::vector<std::string> line_names(const Model& model) {
  std::vector<std::string> names;
  for (const ElementDesc& e : model.elements)
    if (!e.set.empty() && (names.empty() || names.back() != e.set)) names.push_back(e.set);
  return names;
}

void read_displacement(const Field& item, const Model& model,
                       std::map<int, InitialNodeOffset>& offsets) {
  item.expect_map("an initial displacement {line, shape, half_waves, amplitude}");
  item.check_keys({"line", "shape", "half_waves", "amplitude"});
  const Field line = item.child("line");
  const std::string name = line.text();
  const std::vector<int> nodes = line_nodes(model, name);
  if (nodes.size() < 2) {
    const std::vector<std::string> names = line_names(model);
    std::string list;
    for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
    line.fail("no line named '" + name + "';" + did_you_mean(name, names) +
              " lines: " + (list.empty() ? "(none)" : list));
  }
  // A slider's node is not on its path's lines: displacing the path alone would start the
  // slider off it (the constraint then pulls it back in the first step, an impulse).
  for (const Slider& slider : model.sliders)
    for (int e : model.paths[static_cast<size_t>(slider.path)].elements)
      for (int node : model.elements[static_cast<size_t>(e)].nodes)
        if (std::find(nodes.begin(), nodes.end(), node) != nodes.end())
          line.fail("line '" + name + "' carries slider '" + slider.name +
                    "'; an initial displacement would move it from under the slider, whose "
                    "node it does not move: start the line at its static equilibrium or "
                    "reference instead");
  const Field shape = item.child("shape");
  const std::string shape_name = shape.text_or("sine");
  if (shape_name != "sine") shape.fail("unknown shape '" + shape_name + "'; accepted: sine");
  const int n =
      static_cast<int>(item.child("half_waves").integer_or(1, IntRange::between(1, 1000)));
  const Vec3 amplitude = item.child("amplitude").vec3(RealRange::any("m"));
  const Vec3 a = model.nodes[nodes.front()].position, b = model.nodes[nodes.back()].position;
  const double length = (b - a).norm();
  const double k = n * std::numbers::pi / length;
  for (int node : nodes) {
    const double s = (model.nodes[node].position - a).norm();
    InitialNodeOffset& o = offsets[node];
    o.node = node;
    o.displacement += amplitude * std::sin(k * s);
    o.slope += amplitude * (k * std::cos(k * s));
  }
}

void read_initial(const Field& initial, Model& model) {
  InitialConditions& ic = model.dynamic_options.initial;
  if (!initial.present()) return;
  initial.expect_map("initial conditions {from, velocity, displacement}");
  initial.check_keys({"from", "velocity", "displacement"});
  const Field from = initial.child("from");
  const std::string source = from.text_or("static");
  if (source != "static" && source != "reference")
    from.fail("unknown initial state '" + source +
              "'; accepted: static (the equilibrium under "
              "the scene's loads), reference (the mesh, unstressed)");
  ic.from_static = source == "static";
  ic.velocity = initial.child("velocity").vec3_or(ic.velocity, RealRange::any("m/s"));
  std::map<int, InitialNodeOffset> offsets;
  for (const Field& item : initial.child("displacement").items())
    read_displacement(item, model, offsets);
  for (auto& [node, offset] : offsets) ic.offsets.push_back(offset);
}

// `structure`: nonlinear (default), linear about the initial static equilibrium, or modal
// (its modes below `modal_cutoff`); both of the latter start from that equilibrium, which
// must then exist (initial.from: static).
void read_structure(const Field& analysis, Model& model) {
  const Field structure = analysis.child("structure");
  static const std::vector<std::string> choices{"nonlinear", "linear", "modal"};
  const std::string name = structure.text_or("nonlinear");
  if (std::find(choices.begin(), choices.end(), name) == choices.end())
    structure.fail("unknown structure '" + name +
                   "'; accepted: nonlinear (the default), linear "
                   "(cables and beams linearised about the initial static equilibrium), modal "
                   "(the linearised catenary's modes below analysis.modal_cutoff)");
  DynamicOptions& o = model.dynamic_options;
  o.structure = name == "linear"  ? StructureModel::linear
                : name == "modal" ? StructureModel::modal
                                  : StructureModel::nonlinear;
  if (o.structure != StructureModel::nonlinear && !o.initial.from_static)
    structure.fail("a " + name +
                   " structure is linearised about the static equilibrium, so it starts there: "
                   "set analysis.initial.from: static (or leave 'from' out), not reference");
  const Field cutoff = analysis.child("modal_cutoff"), basis = analysis.child("modal_basis");
  if (o.structure != StructureModel::modal) {
    fail_if_present(cutoff, "'modal_cutoff' applies to analysis.structure: modal");
    fail_if_present(basis, "'modal_basis' applies to analysis.structure: modal");
    return;
  }
  o.modal_cutoff = cutoff.real_or(kDefaultModalCutoff, RealRange::positive("Hz"));
  o.modal_basis = basis.text_or("");  // text_or refuses an empty string itself
}

// A fixed step longer than the run would be one step over the whole duration, with
// the step's end clamped to it: almost certainly a unit slip (dt in ms?). An adaptive
// run's dt is only its first step; the driver cuts that to the duration (the app notes it).
void check_step_within_duration(const Field& dt, const Field& duration, const DynamicOptions& o) {
  const IntegratorOptions& in = o.integrator;
  if (in.adaptive || !(in.dt > o.duration)) return;
  const std::string what =
      "integrator.dt = " + format_number(in.dt) + " s" + (dt.present() ? "" : " (the default)") +
      " is longer than analysis.duration = " + format_number(o.duration) +
      " s: a fixed step must not exceed the duration; expected dt <= " + format_number(o.duration) +
      " s (or adaptive: true, where dt is "
      "only the first step)";
  (dt.present() ? dt : duration).fail(what);
}

}  // namespace

namespace {

// Field samples faster than 1 MHz carry nothing a structure's dynamics has (EN 50318 asks
// for 20 Hz of contact force; modes are cut at 100-200 Hz), and more than 10^7 of them fill
// any disk: an interval of 1e-9 s wrote 6.7 GB in a minute and reached t = 0.4 ms.
void check_sample_count(const Field& interval, const Model& model) {
  constexpr double kShortestInterval = 1e-6;  // s
  constexpr double kMostSamples = 1e7;
  const double every = model.output.interval, duration = model.dynamic_options.duration;
  if (every > 0.0 && every < kShortestInterval)
    interval.fail("output.interval = " + format_number(every) +
                  " s is below 1e-6 s (1 MHz sampling); accepted: 0 (every step) or at least "
                  "1e-6 s (EN 50318 evaluates the contact force to 20 Hz)");
  if (every > 0.0 && duration / every > kMostSamples)
    interval.fail("output.interval = " + format_number(every) + " s over " +
                  format_number(duration) + " s makes " + format_number(duration / every) +
                  " field samples; accepted: at most 1e7 (a longer interval, or a shorter run)");
}

}  // namespace

void read_dynamics(const Field& scene, Model& model) {
  const Field analysis = scene.child("analysis");
  const Field output = scene.child("output");
  // A slider's travel along a straight path has no stiffness: the static solve's Newton
  // matrix is singular. A dynamic run's static start holds each slider at its start
  // (apps/catena/static_phase.hpp). Rigid bodies' rotations get theirs from the frame
  // multipliers, which the static solver reaches by a regularised Newton (static_solver.cpp).
  const bool bodies = !model.rigid_bodies.empty();
  const bool sliders = !model.sliders.empty();
  const bool nonlinear_constraints = bodies || sliders;
  if (sliders && model.analysis != AnalysisType::dynamic)
    analysis.child("type").fail(
        "a static analysis with sliders is not available (a slider's travel along a straight "
        "path has no stiffness, and the first Newton matrix is singular); run analysis.type: "
        "dynamic, whose static start holds each slider at its start and releases it at t = 0");
  // The scene's absorbing ends, or a catenary's (`ends: absorbing`, made after shape finding).
  const bool absorbing =
      !model.absorbing_ends.empty() || (model.catenary && model.catenary->absorbing_ends);
  if (absorbing && model.analysis != AnalysisType::dynamic)
    analysis.child("type").fail(
        std::string("absorbing ends act in dynamic runs only (statics would hold them where "
                    "they are: use ") +
        (model.absorbing_ends.empty() ? "catenary.ends: anchored" : "supports") +
        "); run analysis.type: dynamic, whose static start holds them");
  if (model.analysis != AnalysisType::dynamic) {
    const std::string why = " applies to analysis.type: dynamic only";
    fail_if_present(analysis.child("duration"), "'duration'" + why);
    fail_if_present(analysis.child("initial"), "'initial'" + why);
    fail_if_present(analysis.child("structure"),
                    "'structure'" + why + " (statics solves the nonlinear equilibrium)");
    fail_if_present(analysis.child("modal_cutoff"), "'modal_cutoff'" + why);
    fail_if_present(analysis.child("modal_basis"), "'modal_basis'" + why);
    fail_if_present(scene.child("integrator"),
                    "integrator settings apply to analysis.type: dynamic");
    for (const char* key : {"interval", "flush_wall_seconds", "checkpoint_wall_seconds"})
      fail_if_present(output.child(key), std::string("'") + key + "'" + why);
    return;
  }
  const Field duration = analysis.child("duration");
  model.dynamic_options.duration = duration.real(RealRange::positive("s"));
  check_sample_count(output.child("interval"), model);
  read_initial(analysis.child("initial"), model);
  read_structure(analysis, model);
  if (bodies && model.dynamic_options.structure != StructureModel::nonlinear)
    analysis.child("structure")
        .fail("a " + analysis.child("structure").text() +
              " structure with rigid bodies is not available (it linearises the cables and "
              "beams about the static equilibrium; a body's frame and joints stay nonlinear "
              "constraints, which it does not take); use structure: nonlinear");
  if (!model.surfaces.empty() && model.dynamic_options.structure == StructureModel::modal)
    analysis.child("structure")
        .fail(
            "a modal structure with surfaces is not available (the modes are those of the "
            "structure alone, and a contact that comes and goes is no mode); use structure: "
            "linear or nonlinear");
  if (absorbing && model.dynamic_options.structure == StructureModel::modal)
    analysis.child("structure")
        .fail(
            "a modal structure with absorbing ends is not available (an end's dashpot couples "
            "the modes, which the modal model steps apart); use structure: linear or nonlinear");
  if (sliders && model.dynamic_options.structure != StructureModel::nonlinear)
    analysis.child("structure")
        .fail("a " + analysis.child("structure").text() +
              " structure with sliders is not available (a slider runs on the nonlinear "
              "structure's path); use structure: nonlinear");
  read_integrator(scene.child("integrator"), model.constraints.size(), nonlinear_constraints,
                  model.dynamic_options.integrator);
  // Lobatto IIIC's end-of-step multipliers come from the saddle system [M Gᵀ; G 0], linear in
  // λ; a slider's Coulomb friction is not (its force grows with the normal force, λ itself),
  // so they would leave the friction out of every step's end.
  for (const Slider& slider : model.sliders)
    if (slider.friction > 0.0 && model.dynamic_options.integrator.type == "lobatto_iiic")
      scene.child("integrator")
          .child("type")
          .fail("integrator type 'lobatto_iiic' takes no Coulomb friction (slider '" + slider.name +
                "' has friction): its end-of-step multipliers are solved from a system linear "
                "in them, which leaves the friction out; use hht, radau, bdf or park");
  // Adams–Bashforth–Moulton's step limit is 1.28 over the highest frequency of K against M
  // on the nodal unknowns (adams_pece_integrator.hpp); a slider's arc length is one of them
  // and has no mass of its own, so that frequency is undefined.
  if (!model.sliders.empty() && model.dynamic_options.integrator.type == "abm")
    scene.child("integrator")
        .child("type")
        .fail("integrator type 'abm' takes no sliders (slider '" + model.sliders.front().name +
              "'): a slider's arc length has no mass of its own, so the explicit method's "
              "stability limit (from the highest frequency of K against M) is undefined; use "
              "hht, radau, bdf or park");
  check_step_within_duration(scene.child("integrator").child("dt"), duration,
                             model.dynamic_options);
}

}  // namespace catena::model::detail
