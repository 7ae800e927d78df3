#pragma once
// Vectors of s interleaved parts, DOF-major: entry s·g + i holds part i of DOF g (the
// layout of BlockMatrix's rows: the implicit Runge–Kutta stage vectors, and the 2n
// vectors of the decoupled solve's complex-pair blocks). Each rank owns the entries of
// its own DOFs, so splitting and joining never communicate.
#include <petscvec.h>

#include <vector>

#include "catena/assembly/petsc_handle.hpp"

namespace catena::solvers {

// Collective. A vector of `parts` interleaved copies of part's layout (part: a vector
// laid out as the DOFs).
VecHandle create_interleaved_vector(Vec part, int parts);

// Not collective. block → its parts, and back (parts.size() parts, each laid out as the DOFs).
void split_interleaved(Vec block, const std::vector<Vec>& parts);
void join_interleaved(const std::vector<Vec>& parts, Vec block);

}  // namespace catena::solvers
