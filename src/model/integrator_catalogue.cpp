#include "catena/model/integrator_catalogue.hpp"

#include <array>
#include <vector>

namespace catena::model {
namespace {

using M = IntegratorMethod;
using E = EmbeddedEstimate;

// The stage counts: the tableau construction works for any s; beyond order 10 the
// truncation error sinks below double rounding at any step size worth taking. The reasons
// are those of the solvers (irk_integrator.hpp, tableau_decomposition.hpp,
// petsc_ts_integrator.hpp; docs/integrators.md).
constexpr std::string_view kExplicitFirstStage =
    "its explicit first stage leaves the Lagrange multipliers undetermined (singular stage "
    "matrix)";
constexpr std::string_view kRadauFilter = "its filter would need RADAU5's index-3 treatment";

constexpr std::array<IntegratorType, 12> kTypes{{
    {.name = "hht",
     .alias = "",
     .method = M::hht,
     .embedded = E::always,
     .takes_alpha = true,
     .takes_newton = true,
     .takes_local_newton = true,
     .takes_linearly_implicit = true},
    {.name = "central_difference",
     .alias = "",
     .method = M::hht,
     .embedded = E::always,
     .constraint_refusal = "its positions do not depend on the step's unknown (explicit)",
     .takes_newton = true},
    {.name = "rattle", .alias = "", .method = M::rattle, .takes_newton = true},
    {.name = "gauss",
     .alias = "",
     .method = M::irk,
     .min_stages = 1,
     .max_stages = 5,
     .nonlinear_constraint_refusal =
         "its step's end is no stage, so the positions leave nonlinear constraints between "
         "the stages that hold them, and a rigid body's run blew up (meshes/heavy_top.yaml, "
         "dt = 1 ms and 0.25 ms)",
     .takes_newton = true},
    {.name = "radau_iia",
     .alias = "radau",
     .method = M::irk,
     .min_stages = 1,
     .max_stages = 5,
     .embedded = E::odd_stages,
     .embedded_constraint_refusal = kRadauFilter,
     .takes_newton = true},
    {.name = "lobatto_iiia",
     .alias = "",
     .method = M::irk,
     .min_stages = 2,
     .max_stages = 5,
     .constraint_refusal = kExplicitFirstStage,
     .decoupled_refusal = "A is singular (its explicit first stage)",
     .takes_newton = true},
    {.name = "lobatto_iiic",
     .alias = "",
     .method = M::irk,
     .min_stages = 2,
     .max_stages = 5,
     .takes_newton = true},
    {.name = "sdirk",
     .alias = "",
     .method = M::irk,
     .min_stages = 3,
     .max_stages = 3,
     .nonlinear_constraint_refusal =
         "its stage order is 1, and on nonlinear index-3 constraints it does not converge "
         "(meshes/heavy_top.yaml: the top's axis 1.0 rad off at dt = 1 ms, 0.34 rad at 0.25 "
         "ms)",
     .decoupled_refusal = "A has a triple eigenvalue (not diagonalisable)",
     .takes_newton = true},
    {.name = "bdf",
     .alias = "",
     .method = M::multistep,
     .embedded = E::always,
     .takes_newton = true,
     .max_order = 5,
     .multistep = true},
    {.name = "park",
     .alias = "",
     .method = M::multistep,
     .embedded = E::always,
     .takes_newton = true,
     .multistep = true},
    {.name = "abm",
     .alias = "",
     .method = M::multistep,
     .embedded = E::always,
     .max_order = 2,
     .multistep = true},
    {.name = "petsc",
     .alias = "",
     .method = M::petsc_ts,
     .constraint_refusal = "PETSc's TS sees an ODE",
     .takes_alpha = true},
}};

// The name the scene docs use: the alias where there is one ("radau").
std::string_view scene_name(const IntegratorType& t) { return t.alias.empty() ? t.name : t.alias; }

// "a, b <last> c": the items joined by commas, the last by `last` (" or ", " and ").
std::string join(const std::vector<std::string>& items, const char* last) {
  std::string out;
  for (std::size_t i = 0; i < items.size(); ++i)
    out += (i == 0 ? "" : i + 1 == items.size() ? last : ", ") + items[i];
  return out;
}

std::string types_taking_constraints() {
  std::vector<std::string> names;
  for (const IntegratorType& t : kTypes)
    if (t.constraint_refusal.empty()) names.emplace_back(scene_name(t));
  return join(names, " or ");
}

// "hht, central_difference and radau with 1, 3 or 5 stages".
std::string embedded_owners() {
  std::vector<std::string> owners;
  for (const IntegratorType& t : kTypes) {
    if (t.embedded == E::none) continue;
    owners.emplace_back(scene_name(t));
    if (t.embedded == E::odd_stages) {
      std::vector<std::string> odd;
      for (int s = t.min_stages; s <= t.max_stages; ++s)
        if (s % 2 == 1) odd.push_back(std::to_string(s));
      owners.back() += " with " + join(odd, " or ") + " stages";
    }
  }
  return join(owners, " and ");
}

}  // namespace

std::span<const IntegratorType> integrator_types() { return kTypes; }

const IntegratorType* find_integrator_type(std::string_view name) {
  for (const IntegratorType& t : kTypes)
    if (name == t.name || (!t.alias.empty() && name == t.alias)) return &t;
  return nullptr;
}

std::string integrator_type_list() {
  std::string list;
  for (const IntegratorType& t : kTypes) {
    list += (list.empty() ? "" : ", ") + std::string(scene_name(t));
    if (!t.alias.empty()) list += " (= " + std::string(t.name) + ")";
  }
  return list;
}

std::string integrator_names(IntegratorMethod method) {
  std::string list;
  for (const IntegratorType& t : kTypes)
    if (t.method == method) list += (list.empty() ? "" : ", ") + std::string(scene_name(t));
  return list;
}

bool stages_accepted(const IntegratorType& type, int stages) {
  return type.method != M::irk || (stages >= type.min_stages && stages <= type.max_stages);
}

int default_stages(const IntegratorType& type, int fallback) {
  return type.min_stages == type.max_stages && type.method == M::irk ? type.min_stages : fallback;
}

bool has_embedded_estimate(const IntegratorType& type, int stages, bool constrained) {
  if (constrained && !type.embedded_constraint_refusal.empty()) return false;
  switch (type.embedded) {
    case E::none:
      return false;
    case E::always:
      return true;
    case E::odd_stages:
      return stages % 2 == 1;
  }
  return false;
}

std::optional<IntegratorRefusal> refuse_integrator(const IntegratorOptions& options,
                                                   std::size_t constraints,
                                                   bool nonlinear_constraints) {
  const IntegratorType* type = find_integrator_type(options.type);
  if (!type) return std::nullopt;  // unknown types are the reader's (and parser's) business
  const std::string name(type->name);
  const bool irk = type->method == M::irk;
  const std::string stages = irk ? " with " + std::to_string(options.stages) + " stages" : "";
  if (constraints > 0 && !type->constraint_refusal.empty())
    return IntegratorRefusal{
        "type", "integrator type '" + std::string(scene_name(*type)) +
                    "' takes no Lagrange-multiplier constraints (the scene has " +
                    std::to_string(constraints) + "): " + std::string(type->constraint_refusal) +
                    "; with constraints use " + types_taking_constraints() +
                    ", or supports instead of pinned constraints"};
  if (nonlinear_constraints && !type->nonlinear_constraint_refusal.empty())
    return IntegratorRefusal{"type",
                             "integrator type '" + std::string(scene_name(*type)) +
                                 "' takes no rigid bodies or sliders (their frame constraints, "
                                 "joints and slider constraints are nonlinear): " +
                                 std::string(type->nonlinear_constraint_refusal) +
                                 "; use radau, lobatto_iiic, hht, bdf or park"};
  // Measured on meshes/heavy_top.yaml (dt = 1 ms): the multipliers grew until Newton failed
  // at α = 0, −0.01 and −0.02 (after 0.32, 0.48 and 0.72 s); −0.05 to −0.2 ran the 2 s.
  if (nonlinear_constraints && type->takes_alpha && type->method == M::hht && options.alpha > -0.05)
    return IntegratorRefusal{
        "alpha",
        "HHT with alpha = " + std::to_string(options.alpha) +
            " takes no rigid bodies or sliders: with their nonlinear constraints the multipliers "
            "grew without bound at alpha = 0, -0.01 and -0.02 (meshes/heavy_top.yaml); "
            "use alpha <= -0.05 (the default -0.1), or radau"};
  if (options.error_estimate == "embedded" &&
      !has_embedded_estimate(*type, options.stages, constraints > 0)) {
    if (constraints > 0 && has_embedded_estimate(*type, options.stages, false))
      return IntegratorRefusal{
          "error_estimate", name + stages + " has no embedded error estimate with constraints (" +
                                std::string(type->embedded_constraint_refusal) +
                                "); use step_doubling or auto"};
    return IntegratorRefusal{"error_estimate", name + stages + " has no embedded error estimate (" +
                                                   embedded_owners() +
                                                   " have); use step_doubling or auto"};
  }
  if (type->multistep && options.adaptive && options.error_estimate == "step_doubling")
    return IntegratorRefusal{
        "error_estimate",
        name +
            " is a multistep method: step doubling's return to a step's start would restart "
            "its history every step; use embedded or auto (its own estimate)"};
  if (type->name == "bdf" && options.order > 2 && !options.adaptive)
    return IntegratorRefusal{
        "order", "bdf of order " + std::to_string(options.order) +
                     " needs adaptive: true: it starts at order 1 and climbs a step at a time, and "
                     "with fixed steps that start's error (of order dt^2) bounds the whole run's "
                     "accuracy; with adaptive steps the error control takes small first steps; "
                     "or use order 1 or 2"};
  if (irk && options.linear_algebra == "decoupled") {
    std::string why;
    if (options.newton == "full")
      why = "full Newton linearises every stage at its own state (no Kronecker form)";
    else if (!type->decoupled_refusal.empty())
      why = name + "'s " + std::string(type->decoupled_refusal);
    if (!why.empty())
      return IntegratorRefusal{"linear_algebra", "linear_algebra: decoupled is not exact here: " +
                                                     why + "; use auto or coupled"};
  }
  return std::nullopt;
}

}  // namespace catena::model
