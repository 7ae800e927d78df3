#pragma once
// A window of one rank's DOFs in which the residual and the Newton matrix can be
// re-evaluated from a few kernels, without touching the rest of the system.
//
// Why: after one Newton iteration with a stale tangent, the residual of a moving-load or
// contact run is left only near the load, where the kink the load makes in the wire has
// moved since the tangent was evaluated (docs/integrators.md, "Local Newton correction").
// Finishing the solve there costs a few element evaluations, where another global
// iteration costs a residual evaluation and a pair of triangular solves over the whole
// line.
//
// The unknowns are DOFs this rank can change alone: every kernel coupling (an element)
// that touches them is this rank's and touches only DOFs this rank owns, no excluded
// coupling acts on their nodes (a constraint: its forces are not re-evaluated here), and a
// coupling active at the patch's time (a pantograph contact) that acts on them is this
// rank's with all its active DOFs owned (it then counts as a kernel of the patch). Changing
// them then changes the residual only in `rows`, the DOFs of the couplings that touch
// them, all owned. State-independent couplings (moving loads) cancel in such a change.
// SecondOrderSystem builds patches (local_patch) and evaluates on them (patch_force,
// patch_mass_product, patch_matrix); indices are into the owned part of global vectors.
#include <petscsys.h>

#include <cstddef>
#include <vector>

namespace catena::assembly {

struct LocalPatch {
  double t = 0.0;                  // s: the time the couplings' active DOFs are taken at
  std::vector<PetscInt> unknowns;  // owned local indices, ascending
  std::vector<PetscInt> rows;  // owned local indices the couplings touch (⊇ unknowns), ascending
  // This rank's couplings acting on an unknown (indices into its coupling list): the kernel
  // couplings in ascending order, then the n_timed ones active at t (contacts).
  std::vector<size_t> couplings;
  size_t n_timed = 0;
  // Per active DOF of each coupling in `couplings` (concatenated): its position in `rows`,
  // −1 if fixed.
  std::vector<PetscInt> coupling_rows;
  // Per row: its position in `unknowns`, or −1.
  std::vector<PetscInt> unknown_of_row;

  bool empty() const { return unknowns.empty(); }
};

// One entry of a patch matrix: row and column are positions in LocalPatch::unknowns.
struct PatchEntry {
  PetscInt row = 0, col = 0;
  double value = 0.0;
};

}  // namespace catena::assembly
