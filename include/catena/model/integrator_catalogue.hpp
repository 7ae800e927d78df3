#pragma once
// The time integrator types a scene can name (integrator.type) and the facts about each
// that decide what runs: stage counts, which scene keys apply, where an embedded error
// estimate exists, and which combinations with Lagrange-multiplier constraints or the
// decoupled stage solve are refused. One table, asked by the scene reader (which names
// the file, line and key at fault) and by the solvers (make_tableau, make_integrator,
// IrkIntegrator), so that the two cannot disagree. Plain data in the model layer, as the
// model layer cannot see the solvers; the solver tests check each fact against the
// tableaus themselves (test_solvers_integrator_catalogue).
//
// Not collective: no MPI, no PETSc.
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "catena/model/model.hpp"

namespace catena::model {

enum class IntegratorMethod {
  hht,        // HhtIntegrator (HHT-α, or central differences)
  irk,        // IrkIntegrator with the family's Butcher tableau
  petsc_ts,   // PetscTsIntegrator (the method from -ts_type)
  multistep,  // MultistepIntegrator (variable-step BDF, Park), AdamsPeceIntegrator (abm)
  rattle,     // RattleIntegrator (Lobatto IIIA–IIIB, s = 2)
};

// Where a type has an embedded local error estimate (without it, step doubling serves).
enum class EmbeddedEstimate {
  none,
  always,      // HHT (Zienkiewicz & Xie)
  odd_stages,  // Radau IIA with s = 1, 3, 5 (RADAU5's formula; docs/tableaus.md)
};

struct IntegratorType {
  std::string_view name = {};   // canonical, as stored in IntegratorOptions::type
  std::string_view alias = {};  // also accepted, the name the scene docs use ("radau"), or ""
  IntegratorMethod method = IntegratorMethod::hht;
  int min_stages = 0, max_stages = 0;  // IRK only (0 otherwise)
  EmbeddedEstimate embedded = EmbeddedEstimate::none;
  // Why the embedded estimate is not offered with constraints, or "" if it is.
  std::string_view embedded_constraint_refusal = {};
  // Why the type takes no Lagrange-multiplier constraints, or "" if it does.
  std::string_view constraint_refusal = {};
  // Why it takes linear constraints but not nonlinear ones (a rigid body's frame, joints
  // between bodies), or "" if it takes both.
  std::string_view nonlinear_constraint_refusal = {};
  // IRK: why the decoupled stage solve is not exact for this family (its A has no distinct
  // nonzero eigenvalues: tableau_decomposition.hpp), or "" if it is.
  std::string_view decoupled_refusal = {};
  // Which scene keys apply besides the common ones (stages and linear_algebra: IRK only).
  bool takes_alpha = false;              // HHT's α (petsc: for -ts_type alpha2)
  bool takes_newton = false;             // newton: simplified | full
  bool takes_local_newton = false;       // local_newton
  bool takes_linearly_implicit = false;  // newton: linearly_implicit (and tangent_every)
  int max_order = 0;  // order: 1 to max_order (bdf 5, abm 2); 0: the type takes no order
  // A multistep method: its steps depend on those before, so step doubling (whose return
  // to a step's start would restart the history every step) is refused, and orders above
  // 2 need adaptive steps (the start's low-order steps bound a fixed-step run to order 2).
  bool multistep = false;
};

// Every type, in the order messages list them.
std::span<const IntegratorType> integrator_types();

// The type called `name` (canonical or alias), or null.
const IntegratorType* find_integrator_type(std::string_view name);

// The accepted names for messages: "hht, gauss, radau (= radau_iia), ..., petsc".
std::string integrator_type_list();
// The names of the types of one method as the scene docs use them (aliases first):
// "gauss, radau, lobatto_iiia, lobatto_iiic, sdirk" for irk.
std::string integrator_names(IntegratorMethod method);

// True if `stages` is within the type's range (always for types without stages).
bool stages_accepted(const IntegratorType& type, int stages);
// The stage count a scene without `stages` gets: the fixed one where the range has a
// single value (sdirk), else `fallback`.
int default_stages(const IntegratorType& type, int fallback);

// Whether the type with `stages` carries an embedded error estimate, with or without
// constraints.
bool has_embedded_estimate(const IntegratorType& type, int stages, bool constrained);

// A combination of settings the solvers refuse: the key of the integrator map at fault
// (e.g. "error_estimate") and the reason, in a sentence that says what to use instead.
struct IntegratorRefusal {
  std::string key;
  std::string why;
};

// The first combination in `options` (a known type, stages in range) that the solvers
// refuse for a model with `constraints` Lagrange-multiplier constraints, or nothing:
// constraints with a type that takes none (key "type"), error_estimate: embedded where
// there is no embedded estimate ("error_estimate"), linear_algebra: decoupled where it is
// not exact ("linear_algebra"), step doubling for a multistep method ("error_estimate"), a
// BDF order above 2 with fixed steps ("order"); with `nonlinear_constraints` (the model has
// rigid bodies) also the types that take only linear ones ("type").
std::optional<IntegratorRefusal> refuse_integrator(const IntegratorOptions& options,
                                                   std::size_t constraints,
                                                   bool nonlinear_constraints = false);

}  // namespace catena::model
