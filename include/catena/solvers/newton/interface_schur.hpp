#pragma once
// An exact parallel solve of a line's Newton matrix by its partition interface (a Schur
// complement): the rows a rank shares with another rank (its interface: rows with a
// column owned elsewhere, and rows another rank's rows reach) are split from the rest
// (its interior). The interior rows of different ranks never couple, so the interior
// block is block-diagonal by rank and each rank factors its own block sequentially with
// PETSc's LU (the fast solver of docs/performance.md, "Direct solver"); the interface
// unknowns' Schur complement S = A_ΓΓ − A_ΓI A_II⁻¹ A_IΓ is formed explicitly and
// factored redundantly on every rank. A line cut into P pieces has an interface of a few
// nodes per cut, so S is small and the solve is a direct one, independent of the rank
// count to round-off:
//   x_I = A_II⁻¹ (b_I − A_IΓ x_Γ),  x_Γ = S⁻¹ (b_Γ − A_ΓI A_II⁻¹ b_I),
// PETSc's PCFIELDSPLIT (Schur, full factorisation, explicit S), options under
// -<prefix>fieldsplit_interior_ and -<prefix>fieldsplit_interface_.
#include <petscksp.h>

#include <string>

namespace catena::solvers {

// Collective on J. Makes `ksp`'s preconditioner the interface split of J's pattern (J
// assembled with its full pattern). Defaults for the sub-solvers are set unless the
// options database has them. Returns the number of interface rows (all ranks).
long use_interface_schur(KSP ksp, Mat J, const std::string& prefix);

// Collective on ksp. After the matrix's values changed (a new tangent, another step
// size): the split formed again at the next solve. Nothing for any other preconditioner.
void refresh_interface_schur(KSP ksp);

}  // namespace catena::solvers
