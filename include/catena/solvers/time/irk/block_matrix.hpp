#pragma once
// An s×s block matrix built from the system's n×n matrices K, C, M (same sparsity):
//   B_ij = k_ij K + c_ij C + m_ij M + d_ij I ,      i, j = 0..s−1,
// assembled as one MPIAIJ matrix so that MUMPS factors it directly (the IRK stage matrix
// δ_ij M + h a_ij C + h² (A²)_ij K; the first-order form [σI, −I; K, C + σM] of PETSc TS).
//
// Layout: DOF-major interleaving, row s·g + i for global DOF g and block i. Each rank
// keeps its own DOFs' rows (ownership ranges scale by s), and the bandwidth grows by s
// rather than by n as it would with stage-major blocks, which keeps MUMPS's fill low.
#include <petscmat.h>

#include <vector>

#include "catena/assembly/petsc_handle.hpp"

namespace catena::solvers {

struct BlockCoefficients {
  int s = 1;
  std::vector<double> k, c, m, d;  // s×s each, row-major; empty = all zero

  explicit BlockCoefficients(int blocks);
  double& K(int i, int j) { return k[static_cast<size_t>(i * s + j)]; }
  double& C(int i, int j) { return c[static_cast<size_t>(i * s + j)]; }
  double& M(int i, int j) { return m[static_cast<size_t>(i * s + j)]; }
  double& I(int i, int j) { return d[static_cast<size_t>(i * s + j)]; }
};

class BlockMatrix {
 public:
  // Collective. `pattern`: an assembled n×n MPIAIJ matrix whose nonzero pattern K, C and
  // M share (SecondOrderSystem::create_matrix() with entries, diagonal included).
  BlockMatrix(Mat pattern, int blocks);

  int blocks() const { return s_; }
  Mat matrix() const { return B_.get(); }
  // Collective. B = Σ blocks as above (K, C or M may be null where all their
  // coefficients are zero). The pattern never changes, so MUMPS's analysis is reused.
  void assemble(Mat K, Mat C, Mat M, const BlockCoefficients& coefficients);
  // Collective. As above, with block row i taking K_rows[i] and C_rows[i] (each list of
  // size s; entries may be null where their coefficients are zero): the full Newton matrix
  // of an IRK step, whose stage i is linearised at its own state.
  void assemble_rows(const std::vector<Mat>& K_rows, const std::vector<Mat>& C_rows, Mat M,
                     const BlockCoefficients& coefficients);

  // Collective. A vector laid out as B's rows (split and join it with
  // interleaved_vectors.hpp).
  VecHandle create_vector() const;

 private:
  int s_;
  PetscInt n_owned_ = 0, first_ = 0;
  MatHandle B_;
};

}  // namespace catena::solvers
