#pragma once
// Whether stored modes are the modes of a structure: the test a modal run applies before
// it uses a modal basis written by another run (io/modal_basis.hpp), so that a basis is
// never applied to a structure it was not computed for — whatever changed in the scene.
#include <petscmat.h>

#include <string>
#include <vector>

namespace catena::solvers {

// Collective. "" if `shapes` (laid out as K's columns, zero outside `keep`) with
// `frequency` (Hz) are every mode of K φ = ω² M φ over the DOFs `keep` (this rank's
// owned global indices, ascending) below `cutoff` (Hz): each pair's relative residual
// |K φ − ω² M φ| / (ω² |M φ|) and its modal mass's distance from 1 within `tolerance`,
// each M-orthogonal to the next (to `tolerance`: no mode twice), and as many pairs as
// K − (2π cutoff)² M has negative eigenvalues over `keep` (the inertia of its MUMPS LDLᵀ). Else why
// not, in words, naming the first mode or the count that fails.
std::string modes_mismatch(Mat K, Mat M, const std::vector<PetscInt>& keep, double cutoff,
                           const std::vector<double>& frequency, const std::vector<Vec>& shapes,
                           double tolerance);

}  // namespace catena::solvers
