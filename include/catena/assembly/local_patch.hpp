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
// The unknowns are DOFs this rank can change alone: every kernel that touches them is
// this rank's and touches only DOFs this rank owns, no constraint acts on them (its
// forces are not re-evaluated here), and a moving contact that acts on them at the
// patch's time is this rank's with all its DOFs owned (it then counts as a kernel of the
// patch). Changing them then changes the residual only in `rows`, the DOFs of the
// kernels and contacts that touch them, all owned.
// SecondOrderSystem builds patches (local_patch) and evaluates on them (patch_force,
// patch_mass_product, patch_matrix); indices are into the owned part of global vectors.
#include <petscsys.h>

#include <cstddef>
#include <vector>

namespace catena::assembly {

struct LocalPatch {
  std::vector<PetscInt> unknowns;  // owned local indices, ascending
  std::vector<PetscInt> rows;      // owned local indices the kernels touch (⊇ unknowns), ascending
  std::vector<size_t> kernels;     // this rank's kernels touching an unknown
  // Per DOF of each kernel in `kernels` (concatenated): its position in `rows`, −1 if fixed.
  std::vector<PetscInt> kernel_rows;
  // Per row: its position in `unknowns`, or −1.
  std::vector<PetscInt> unknown_of_row;
  // Moving contacts acting on the unknowns (this rank's, indices into its contact list),
  // at time t, with the position in `rows` of each of their 15 DOFs (−1: fixed).
  double t = 0.0;
  std::vector<size_t> contacts;
  std::vector<PetscInt> contact_rows;

  bool empty() const { return unknowns.empty(); }
};

// One entry of a patch matrix: row and column are positions in LocalPatch::unknowns.
struct PatchEntry {
  PetscInt row = 0, col = 0;
  double value = 0.0;
};

}  // namespace catena::assembly
