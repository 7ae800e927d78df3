#pragma once
// A copy of an assembled AIJ matrix without its explicitly stored zeros.
//
// The system's matrices (SecondOrderSystem::jacobian, tangent_parts) insert every entry
// of the full element pattern, zero or not, so that all of them share one nonzero
// pattern (MatAXPY with SAME_NONZERO_PATTERN, one symbolic factorisation). A matrix that
// is only multiplied, never combined, does not need that pattern: the ANCF mass matrix
// couples a DOF only with the same component of its element's nodes (S ⊗ I₃), 6 of the
// 18 entries of a cable row, and its product M·a in every HHT residual costs a third as
// much in the compact copy. The product is the same up to the order of the additions
// (round-off): a dropped entry contributed an exact 0·x.
#include <petscmat.h>

#include "catena/assembly/petsc_handle.hpp"

namespace catena::assembly {

// Collective. A new MATAIJ with A's layout holding A's nonzero entries (exactly
// preallocated); A must be assembled.
MatHandle compact_copy(Mat A);

}  // namespace catena::assembly
