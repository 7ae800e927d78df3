#pragma once
// A starting point for the static solve of cables that hang under their own weight: the
// closed-form elastic catenary (Irvine, "Cable Structures", MIT Press 1981, §2.2) of each
// line, so that a slack, stiff line (a mooring line) reaches its equilibrium in a handful
// of Newton iterations instead of a long walk along the load path from the straight
// reference.
//
// It applies to a model made only of such lines: every element an ANCF cable, each line a
// chain of cables with one section (EA, mass, prestrain) between two pinned nodes (position
// fixed, slope free), its interior nodes shared by exactly two of its elements and held
// nowhere except where the catenary already has the reference value (a planar line's y),
// loaded by gravity alone (no nodal or distributed loads, point masses, elastic supports,
// constraints, moving loads or pantographs). Anything else: no guess, and the solver walks
// the load path as before.
#include <petscvec.h>

#include <optional>
#include <string>
#include <vector>

#include "catena/assembly/petsc_handle.hpp"
#include "catena/assembly/second_order_system.hpp"
#include "catena/core/vec3.hpp"
#include "catena/model/model.hpp"
#include "catena/solvers/statics/static_solver.hpp"

namespace catena::solvers {

// A node's place in the guess: its position and its ANCF slope r_x (per unit of the
// element's mesh coordinate).
struct NodeGuess {
  int node = 0;
  Vec3 position = Vec3::Zero();
  Vec3 slope = Vec3::Zero();
};

// Not collective. The elastic catenary at the nodes of every line, or nothing when the
// model is not made of hanging lines alone (see the file comment).
std::optional<std::vector<NodeGuess>> hanging_cable_guess(const model::Model& model);

// Not collective. The catenary of one cable of unstretched length L0, axial stiffness EA
// and weight q (N per unit unstretched length, along `down`) between a and b: the
// position and the tangent dp/ds0 at unstretched arc lengths s (from a). Empty when it has
// no solution the method finds (a vertical chord, or no convergence).
struct CatenaryPoint {
  Vec3 position, tangent;
};
std::optional<std::vector<CatenaryPoint>> elastic_catenary_points(const Vec3& a, const Vec3& b,
                                                                  double L0, double EA, double q,
                                                                  const Vec3& down,
                                                                  const std::vector<double>& s);

// Collective. q: the reference state with the guessed nodes' position and slope DOFs set
// (absolute values, as the state holds them).
void set_guess(const assembly::SecondOrderSystem& system, const std::vector<NodeGuess>& guess,
               Vec q);

// Collective. The reference state with the system's model's hanging_cable_guess set, for
// StaticSolver::solve; a null handle when none applies.
VecHandle hanging_cable_start(const assembly::SecondOrderSystem& system);

// Not collective. A line for the run's log saying what became of the guess ("" if none).
std::string describe_guess(GuessOutcome outcome);

}  // namespace catena::solvers
