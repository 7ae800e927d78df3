#include "catena/solvers/newton/interface_schur.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <vector>

#include "catena/assembly/petsc_call.hpp"
#include "catena/assembly/petsc_handle.hpp"
#include "catena/solvers/newton/constraints_last_ordering.hpp"

namespace catena::solvers {
namespace {

PetscInt petsc(Eigen::Index n) { return static_cast<PetscInt>(n); }

// Rows coupled to more than this many unknowns of other ranks are hubs: a pantograph's,
// whose contact can reach any element of the part of its wire it crosses in the run (the
// pattern holds them all).
// A hub joins the interface alone; its neighbours need not.
constexpr PetscInt kHubColumns = 64;

// This rank's rows of J (global numbers, ascending): interior and interface, and the
// multipliers' rows among the latter (constraints_last_ordering.hpp).
struct RowSplit {
  std::vector<PetscInt> interior, interface, constraints;
};

// Collective. The off-process block's pattern (garray: its columns' global numbers) holds
// every coupling between ranks, in the row of one rank or the other; the interface must
// hold one end of each: the hubs, and every other row with an entry to a non-hub.
RowSplit split_rows(Mat J) {
  PetscInt first = 0, end = 0;
  CATENA_PETSC(MatGetOwnershipRange(J, &first, &end));
  Mat diagonal = nullptr, off = nullptr;
  const PetscInt* garray = nullptr;
  CATENA_PETSC(MatMPIAIJGetSeqAIJ(J, &diagonal, &off, &garray));
  PetscInt n_rows = 0, n_columns = 0;
  CATENA_PETSC(MatGetSize(off, nullptr, &n_columns));
  const PetscInt *ia = nullptr, *ja = nullptr;
  PetscBool done = PETSC_FALSE;
  CATENA_PETSC(MatGetRowIJ(off, 0, PETSC_FALSE, PETSC_FALSE, &n_rows, &ia, &ja, &done));
  if (!done) throw Error("interface Schur solve: the off-process block gives no row structure");
  VecHandle hubs;
  CATENA_PETSC(MatCreateVecs(J, hubs.out(), nullptr));
  {
    PetscScalar* h = nullptr;
    CATENA_PETSC(VecGetArray(hubs.get(), &h));
    for (PetscInt i = 0; i < n_rows; ++i) h[i] = ia[i + 1] - ia[i] > kHubColumns ? 1.0 : 0.0;
    CATENA_PETSC(VecRestoreArray(hubs.get(), &h));
  }
  // Whether each off-process column is a hub, from its owner.
  VecHandle column_hubs;
  CATENA_PETSC(VecCreateSeq(PETSC_COMM_SELF, n_columns, column_hubs.out()));
  {
    IsHandle from;
    CATENA_PETSC(
        ISCreateGeneral(PETSC_COMM_SELF, n_columns, garray, PETSC_USE_POINTER, from.out()));
    VecScatter scatter = nullptr;
    CATENA_PETSC(VecScatterCreate(hubs.get(), from.get(), column_hubs.get(), nullptr, &scatter));
    CATENA_PETSC(
        VecScatterBegin(scatter, hubs.get(), column_hubs.get(), INSERT_VALUES, SCATTER_FORWARD));
    CATENA_PETSC(
        VecScatterEnd(scatter, hubs.get(), column_hubs.get(), INSERT_VALUES, SCATTER_FORWARD));
    CATENA_PETSC(VecScatterDestroy(&scatter));
  }
  RowSplit split;
  // A multiplier's row has no diagonal of its own: the interior blocks, factored without
  // pivoting, must not hold one; in the interface its pivot is the Schur complement's.
  split.constraints = constraint_rows(J);
  {
    const PetscScalar *h = nullptr, *column_hub = nullptr;
    CATENA_PETSC(VecGetArrayRead(hubs.get(), &h));
    CATENA_PETSC(VecGetArrayRead(column_hubs.get(), &column_hub));
    for (PetscInt i = 0; i < n_rows; ++i) {
      bool shared = h[i] > 0.0 || std::binary_search(split.constraints.begin(),
                                                     split.constraints.end(), first + i);
      for (PetscInt k = ia[i]; k < ia[i + 1] && !shared; ++k) shared = column_hub[ja[k]] == 0.0;
      (shared ? split.interface : split.interior).push_back(first + i);
    }
    CATENA_PETSC(VecRestoreArrayRead(column_hubs.get(), &column_hub));
    CATENA_PETSC(VecRestoreArrayRead(hubs.get(), &h));
  }
  CATENA_PETSC(MatRestoreRowIJ(off, 0, PETSC_FALSE, PETSC_FALSE, &n_rows, &ia, &ja, &done));
  return split;
}

// The solve. Per factorisation: this rank's interior block A_II (PETSc's LU, nested
// dissection, the symbolic part once; factored in place, see factor_interior), W = A_II⁻¹ A_IΓ
// for the interface columns its interior touches, and S = A_ΓΓ − Σ_ranks A_CI W (C: the interface
// rows coupled to the rank's interior). S is sparse — on a line each cut couples only to its
// neighbours, a hub to everything — so every rank contributes a small dense block (C × touched
// columns) and its own rows of A_ΓΓ; the terms are gathered on every rank, summed in rank order
// (the same bits everywhere) into a sparse S and factored there by PETSc's LU (nested dissection,
// symbolic once; no pivoting: S is a Schur complement of a matrix that needs none). Per solve: y =
// A_II⁻¹ b_I, x_Γ = S⁻¹ (b_Γ − Σ A_CI y), x_I = y − W x_Γ: one interior solve, a product with W's
// few columns and one allreduce of n_Γ numbers. What grows with the rank count P: n_Γ (about 12 per
// cut on a cable line), the gathered terms (P small blocks) and the allreduce (n_Γ numbers); a
// dense S would cost n_Γ² memory and n_Γ³ work per factorisation on every rank.
class InterfaceSchur {
 public:
  InterfaceSchur(MPI_Comm comm, const RowSplit& split, PetscInt first, PetscInt n_local)
      : comm_(comm), first_row_(first), n_local_(n_local) {
    for (PetscInt row : split.interior) interior_local_.push_back(row - first);
    int size = 1;
    MPI_Comm_size(comm, &size);
    // Every rank's interface rows; ranks own ascending ranges, so rank order is ascending.
    const int n_mine = static_cast<int>(split.interface.size());
    std::vector<int> counts(static_cast<std::size_t>(size)), offsets(counts.size(), 0);
    MPI_Allgather(&n_mine, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
    std::partial_sum(counts.begin(), counts.end() - 1, offsets.begin() + 1);
    interface_.resize(static_cast<std::size_t>(offsets.back() + counts.back()));
    MPI_Allgatherv(split.interface.data(), n_mine, MPIU_INT, interface_.data(), counts.data(),
                   offsets.data(), MPIU_INT, comm);
    MPI_Comm_rank(comm, &rank_);
    for (int k = 0; k < n_mine; ++k) {
      owned_local_.push_back(split.interface[static_cast<std::size_t>(k)] - first);
      owned_position_.push_back(offsets[static_cast<std::size_t>(rank_)] + k);
    }
    // Every rank's multiplier rows, as places in interface_ (S's rows).
    const int n_constraints = static_cast<int>(split.constraints.size());
    MPI_Allgather(&n_constraints, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
    std::partial_sum(counts.begin(), counts.end() - 1, offsets.begin() + 1);
    std::vector<PetscInt> constraints(static_cast<std::size_t>(offsets.back() + counts.back()));
    MPI_Allgatherv(split.constraints.data(), n_constraints, MPIU_INT, constraints.data(),
                   counts.data(), offsets.data(), MPIU_INT, comm);
    for (const PetscInt row : constraints)
      schur_constraints_.push_back(static_cast<PetscInt>(
          std::lower_bound(interface_.begin(), interface_.end(), row) - interface_.begin()));
    CATENA_PETSC(ISCreateGeneral(PETSC_COMM_SELF, static_cast<PetscInt>(split.interior.size()),
                                 split.interior.data(), PETSC_COPY_VALUES, interior_.out()));
    CATENA_PETSC(ISCreateGeneral(PETSC_COMM_SELF, static_cast<PetscInt>(interface_.size()),
                                 interface_.data(), PETSC_COPY_VALUES, interface_is_.out()));
    CATENA_PETSC(ISCreateStride(PETSC_COMM_SELF, n_local, first, 1, local_is_.out()));
  }

  ~InterfaceSchur() {
    if (blocks_) MatDestroySubMatrices(2, &blocks_);
  }

  long interface_size() const { return static_cast<long>(interface_.size()); }

  // Collective. Factors A (the pattern of the first call at every call); false if a pivot
  // vanished (then apply() returns NaN until a later setup succeeds).
  bool setup(Mat A) {
    ready_ = false;
    PetscObjectState pattern = 0;
    CATENA_PETSC(MatGetNonzeroState(A, &pattern));
    if (blocks_ && pattern != pattern_)
      throw Error(
          "interface Schur solve: the matrix's nonzero pattern changed after its split "
          "(the split, the symbolic factorisation and W's columns rest on it)");
    pattern_ = pattern;
    if (!blocks_) find_coupled_rows(A);
    // The two small blocks, one call: A_IΓ (this rank's rows), A_CI (the coupled interface
    // rows, fetched from their owners; the columns of all this rank's rows, those of its
    // interface meeting the zeros of y's and W's interface rows).
    IS rows[2] = {interior_.get(), coupled_is_.get()};
    IS cols[2] = {interface_is_.get(), local_is_.get()};
    CATENA_PETSC(MatCreateSubMatrices(A, 2, rows, cols,
                                      blocks_ ? MAT_REUSE_MATRIX : MAT_INITIAL_MATRIX, &blocks_));
    const Mat Aig = blocks_[0], Aci = blocks_[1];
    Mat local = nullptr;  // this rank's diagonal block: its rows, its columns
    CATENA_PETSC(MatMPIAIJGetSeqAIJ(A, &local, nullptr, nullptr));
    const auto n_i = static_cast<Eigen::Index>(interior_local_.size());
    const auto n_c = static_cast<Eigen::Index>(coupled_position_.size());
    // The interior factorisation is this rank's alone; its outcome is agreed before the
    // collective work below, so that an error on one rank is an error on every rank, not a
    // hang: 2 factored, 1 a vanishing pivot, 0 an error.
    int outcome = 2;
    std::string error_text;
    if (n_i > 0) {
      try {
        if (!factor_) {
          find_interface_slots(local);
          CATENA_PETSC(MatGetFactor(local, MATSOLVERPETSC, MAT_FACTOR_LU, factor_.out()));
          CATENA_PETSC(MatGetOrdering(local, MATORDERINGND, row_order_.out(), column_order_.out()));
          const MatFactorInfo info = factor_info();
          CATENA_PETSC(MatLUFactorSymbolic(factor_.get(), local, row_order_.get(),
                                           column_order_.get(), &info));
          touched_ = touched_columns(Aig);
          CATENA_PETSC(VecCreateSeq(PETSC_COMM_SELF, n_local_, b_local_.out()));
          CATENA_PETSC(VecCreateSeq(PETSC_COMM_SELF, n_local_, y_local_.out()));
          CATENA_PETSC(VecCreateSeq(PETSC_COMM_SELF, petsc(n_c), t_coupled_.out()));
        }
        outcome = factor_interior(local) ? 2 : 1;
      } catch (const std::exception& e) {
        outcome = 0;
        error_text = e.what();
      }
    }
    MPI_Allreduce(MPI_IN_PLACE, &outcome, 1, MPI_INT, MPI_MIN, comm_);
    if (outcome == 0)
      throw Error(error_text.empty() ? "interface Schur solve: another rank's interior "
                                       "factorisation failed"
                                     : error_text);
    if (outcome == 1) return false;
    // This rank's terms of S, in an order that is the same at every setup (the pattern is):
    // −A_CI W by touched column, then A_ΓΓ's entries of the interface rows it owns.
    std::vector<PetscScalar> values;
    std::vector<PetscInt> rows_of, columns_of;  // their places in S (first setup only)
    const bool first = !schur_built_;
    const auto n_t = static_cast<Eigen::Index>(touched_.size());
    W_.clear();
    if (n_i > 0 && n_t > 0) {
      solve_for_touched_columns(Aig);
      // −A_CI W, column by column: the coupled rows of the touched columns of S.
      for (Eigen::Index k = 0; k < n_t; ++k) {
        const SparseColumn& column = W_[static_cast<std::size_t>(k)];
        PetscScalar* w = nullptr;
        CATENA_PETSC(VecSet(b_local_.get(), 0.0));
        CATENA_PETSC(VecGetArray(b_local_.get(), &w));
        for (std::size_t e = 0; e < column.rows.size(); ++e) w[column.rows[e]] = column.values[e];
        CATENA_PETSC(VecRestoreArray(b_local_.get(), &w));
        CATENA_PETSC(MatMult(Aci, b_local_.get(), t_coupled_.get()));
        const PetscScalar* t = nullptr;
        CATENA_PETSC(VecGetArrayRead(t_coupled_.get(), &t));
        for (Eigen::Index r = 0; r < n_c; ++r) {
          values.push_back(-t[r]);
          if (first) {
            rows_of.push_back(petsc(coupled_position_[static_cast<std::size_t>(r)]));
            columns_of.push_back(petsc(touched_[static_cast<std::size_t>(k)]));
          }
        }
        CATENA_PETSC(VecRestoreArrayRead(t_coupled_.get(), &t));
      }
    }
    for (std::size_t k = 0; k < owned_local_.size(); ++k) {
      const PetscInt row = owned_local_[k] + first_row_;
      PetscInt n = 0;
      const PetscInt* c = nullptr;
      const PetscScalar* v = nullptr;
      CATENA_PETSC(MatGetRow(A, row, &n, &c, &v));
      for (PetscInt e = 0; e < n; ++e) {
        const auto at = std::lower_bound(interface_.begin(), interface_.end(), c[e]);
        if (at == interface_.end() || *at != c[e]) continue;
        values.push_back(v[e]);
        if (first) {
          rows_of.push_back(petsc(owned_position_[k]));
          columns_of.push_back(static_cast<PetscInt>(at - interface_.begin()));
        }
      }
      CATENA_PETSC(MatRestoreRow(A, row, &n, &c, &v));
    }
    if (first) build_schur_pattern(rows_of, columns_of, values.size());
    schur_built_ = true;
    if (!assemble_and_factor_schur(values)) return false;
    ready_ = true;
    return true;
  }

  // Collective. x = A⁻¹ b; NaN after a failed setup (every rank alike: the failure is
  // agreed), which the KSP reports as the PC's failure.
  void apply(Vec b, Vec x) const {
    if (!ready_) {
      CATENA_PETSC(VecSet(x, std::numeric_limits<double>::quiet_NaN()));
      return;
    }
    const auto n_i = static_cast<Eigen::Index>(interior_local_.size());
    const auto n_g = static_cast<Eigen::Index>(interface_.size());
    const PetscScalar* bb = nullptr;
    CATENA_PETSC(VecGetArrayRead(b, &bb));
    Eigen::VectorXd r = Eigen::VectorXd::Zero(n_g);
    for (std::size_t k = 0; k < owned_local_.size(); ++k)
      r(owned_position_[k]) = bb[owned_local_[k]];
    PetscScalar* y = nullptr;
    if (n_i > 0) {
      // y = Ã⁻¹ (b_I, 0): A_II⁻¹ b_I in the interior rows, 0 in the interface rows.
      PetscScalar* bl = nullptr;
      CATENA_PETSC(VecGetArrayWrite(b_local_.get(), &bl));
      std::copy(bb, bb + n_local_, bl);
      for (const PetscInt row : owned_local_) bl[row] = 0.0;
      CATENA_PETSC(VecRestoreArrayWrite(b_local_.get(), &bl));
      CATENA_PETSC(MatSolve(factor_.get(), b_local_.get(), y_local_.get()));
      CATENA_PETSC(VecGetArray(y_local_.get(), &y));
      // Exact zeros already (identity rows); set all the same, as A_CI's columns meet them.
      for (const PetscInt row : owned_local_) y[row] = 0.0;
      CATENA_PETSC(VecRestoreArray(y_local_.get(), &y));
      CATENA_PETSC(MatMult(blocks_[1], y_local_.get(), t_coupled_.get()));
      const PetscScalar* t = nullptr;
      CATENA_PETSC(VecGetArrayRead(t_coupled_.get(), &t));
      for (std::size_t c = 0; c < coupled_position_.size(); ++c) r(coupled_position_[c]) -= t[c];
      CATENA_PETSC(VecRestoreArrayRead(t_coupled_.get(), &t));
    }
    CATENA_PETSC(VecRestoreArrayRead(b, &bb));
    MPI_Allreduce(MPI_IN_PLACE, r.data(), static_cast<int>(n_g), MPI_DOUBLE, MPI_SUM, comm_);
    Eigen::VectorXd x_interface(n_g);
    if (n_g > 0) {
      CATENA_PETSC(VecPlaceArray(r_interface_.get(), r.data()));
      CATENA_PETSC(VecPlaceArray(x_interface_.get(), x_interface.data()));
      CATENA_PETSC(MatSolve(schur_factor_.get(), r_interface_.get(), x_interface_.get()));
      CATENA_PETSC(VecResetArray(x_interface_.get()));
      CATENA_PETSC(VecResetArray(r_interface_.get()));
    }
    PetscScalar* xx = nullptr;
    CATENA_PETSC(VecGetArray(x, &xx));
    if (n_i > 0) {
      CATENA_PETSC(VecGetArray(y_local_.get(), &y));
      for (std::size_t k = 0; k < W_.size(); ++k) {
        const double x_k = x_interface(touched_[static_cast<Eigen::Index>(k)]);
        const SparseColumn& column = W_[k];
        for (std::size_t e = 0; e < column.rows.size(); ++e)
          y[column.rows[e]] -= column.values[e] * x_k;
      }
      std::copy(y, y + n_local_, xx);  // the interface rows' are set below
      CATENA_PETSC(VecRestoreArray(y_local_.get(), &y));
    }
    for (std::size_t k = 0; k < owned_local_.size(); ++k)
      xx[owned_local_[k]] = x_interface(owned_position_[k]);
    CATENA_PETSC(VecRestoreArray(x, &xx));
  }

 private:
  // PCLU's defaults (MatFactorInfoInitialize zeroes them): a pivot below 100 ε is zero.
  static MatFactorInfo factor_info() {
    MatFactorInfo info;
    CATENA_PETSC(MatFactorInfoInitialize(&info));
    info.fill = 5.0;
    info.zeropivot = 100.0 * PETSC_MACHINE_EPSILON;
    info.pivotinblocks = 1.0;
    return info;
  }

  // The numeric LU of `matrix` into `factor` (its symbolic part done); false on a zero pivot,
  // one below 100 ε × `scale` (not sticky: the next factorisation starts clean).
  static bool factor_numeric(Mat factor, Mat matrix, double scale = 1.0) {
    MatFactorInfo info = factor_info();
    info.zeropivot *= scale;
    CATENA_PETSC(MatFactorClearError(factor));
    CATENA_PETSC(MatLUFactorNumeric(factor, matrix, &info));
    MatFactorError error = MAT_FACTOR_NOERROR;
    CATENA_PETSC(MatFactorGetError(factor, &error));
    return error == MAT_FACTOR_NOERROR;
  }

  // First setup, collective: the interface rows with an entry in this rank's interior
  // columns (the rows of A_ΓI that are not empty). Only they enter A_CI, so that later
  // setups fetch a few rows per rank instead of every interface row.
  void find_coupled_rows(Mat A) {
    Mat* all = nullptr;
    IS rows = interface_is_.get(), cols = interior_.get();
    CATENA_PETSC(MatCreateSubMatrices(A, 1, &rows, &cols, MAT_INITIAL_MATRIX, &all));
    std::vector<PetscInt> coupled;
    const auto n_g = static_cast<PetscInt>(interface_.size());
    for (PetscInt r = 0; r < n_g; ++r) {
      PetscInt n = 0;
      CATENA_PETSC(MatGetRow(all[0], r, &n, nullptr, nullptr));
      if (n > 0) {
        coupled.push_back(interface_[static_cast<std::size_t>(r)]);
        coupled_position_.push_back(static_cast<Eigen::Index>(r));
      }
      CATENA_PETSC(MatRestoreRow(all[0], r, &n, nullptr, nullptr));
    }
    CATENA_PETSC(MatDestroySubMatrices(1, &all));
    CATENA_PETSC(ISCreateGeneral(PETSC_COMM_SELF, static_cast<PetscInt>(coupled.size()),
                                 coupled.data(), PETSC_COPY_VALUES, coupled_is_.out()));
  }

  // W = A_II⁻¹ A_IΓ on the touched columns, a solve of Ã each (rows of all this rank's
  // unknowns, the interface's zero), kept as its nonzeros only: the inverse of a Newton
  // matrix decays away from the cut until its entries underflow to exact zeros (on the
  // 10 km line at np 2 a column has 550–23 000 nonzeros of 120 000 rows), so the sparse W
  // gives the dense W's products bit for bit, in a fraction of the memory and the time.
  void solve_for_touched_columns(Mat Aig) {
    const auto n_t = touched_.size();
    const auto n_i = static_cast<PetscInt>(interior_local_.size());
    std::vector<Eigen::Index> column_of(interface_.size(), -1);
    for (std::size_t k = 0; k < n_t; ++k)
      column_of[static_cast<std::size_t>(touched_[static_cast<Eigen::Index>(k)])] =
          static_cast<Eigen::Index>(k);
    // A_IΓ by column: (local row, value).
    std::vector<std::vector<std::pair<PetscInt, PetscScalar>>> entries(n_t);
    for (PetscInt i = 0; i < n_i; ++i) {
      PetscInt n = 0;
      const PetscInt* c = nullptr;
      const PetscScalar* v = nullptr;
      CATENA_PETSC(MatGetRow(Aig, i, &n, &c, &v));
      for (PetscInt k = 0; k < n; ++k) {
        const Eigen::Index column = column_of[static_cast<std::size_t>(c[k])];
        CATENA_ASSERT(column >= 0, "interface Schur solve: a column outside the pattern");
        entries[static_cast<std::size_t>(column)].emplace_back(
            interior_local_[static_cast<std::size_t>(i)], v[k]);
      }
      CATENA_PETSC(MatRestoreRow(Aig, i, &n, &c, &v));
    }
    std::vector<char> interface_row(static_cast<std::size_t>(n_local_), 0);
    for (const PetscInt row : owned_local_) interface_row[static_cast<std::size_t>(row)] = 1;
    W_.resize(n_t);
    for (std::size_t k = 0; k < n_t; ++k) {
      PetscScalar* b = nullptr;
      CATENA_PETSC(VecSet(b_local_.get(), 0.0));
      CATENA_PETSC(VecGetArray(b_local_.get(), &b));
      for (const auto& [row, value] : entries[k]) b[row] = value;
      CATENA_PETSC(VecRestoreArray(b_local_.get(), &b));
      CATENA_PETSC(MatSolve(factor_.get(), b_local_.get(), y_local_.get()));
      const PetscScalar* w = nullptr;
      CATENA_PETSC(VecGetArrayRead(y_local_.get(), &w));
      for (PetscInt row = 0; row < n_local_; ++row)
        if (w[row] != 0.0 && !interface_row[static_cast<std::size_t>(row)]) {
          W_[k].rows.push_back(row);
          W_[k].values.push_back(w[row]);
        }
      CATENA_PETSC(VecRestoreArrayRead(y_local_.get(), &w));
    }
  }

  // First setup: where the values of this rank's interface rows sit in its diagonal
  // block's value array (each row's range and its diagonal).
  void find_interface_slots(Mat local) {
    PetscInt n = 0;
    const PetscInt *ia = nullptr, *ja = nullptr;
    PetscBool done = PETSC_FALSE;
    CATENA_PETSC(MatGetRowIJ(local, 0, PETSC_FALSE, PETSC_FALSE, &n, &ia, &ja, &done));
    if (!done) throw Error("interface Schur solve: the diagonal block gives no row structure");
    for (const PetscInt row : owned_local_) {
      const PetscInt* at = std::find(ja + ia[row], ja + ia[row + 1], row);
      if (at == ja + ia[row + 1])
        throw Error("interface Schur solve: row " + std::to_string(first_row_ + row) +
                    " has no diagonal entry in the pattern (SecondOrderSystem::create_matrix "
                    "gives every row one)");
      interface_slots_.push_back({ia[row], ia[row + 1], static_cast<PetscInt>(at - ja)});
    }
    CATENA_PETSC(MatRestoreRowIJ(local, 0, PETSC_FALSE, PETSC_FALSE, &n, &ia, &ja, &done));
  }

  // The interior block's LU without a copy of it: this rank's diagonal block with its
  // interface rows made identity rows, Ã = [A_II A_IΓ; 0 I], factored in place and given its
  // values back. Ã is block triangular, so Ã⁻¹ (b_I, 0) = (A_II⁻¹ b_I, 0), and eliminating an
  // identity row changes no other (its multipliers are zeros): Ã's pivots are A_II's, in the
  // order nested dissection gives A_II's rows within the block's. The copy of A_II this
  // replaces was nearly as large as the block (the 10 km line at np 2: 89 MB of both ranks'
  // memory in PETSc's log, MatCreateSubMatrices).
  bool factor_interior(Mat local) {
    PetscScalar* a = nullptr;
    saved_values_.clear();
    CATENA_PETSC(MatSeqAIJGetArray(local, &a));
    for (const Slots& row : interface_slots_)
      for (PetscInt k = row.begin; k < row.end; ++k) {
        saved_values_.push_back(a[k]);
        a[k] = k == row.diagonal ? 1.0 : 0.0;
      }
    CATENA_PETSC(MatSeqAIJRestoreArray(local, &a));
    const auto restore = [&] {
      PetscScalar* values = nullptr;
      if (MatSeqAIJGetArray(local, &values)) return;
      std::size_t at = 0;
      for (const Slots& row : interface_slots_)
        for (PetscInt k = row.begin; k < row.end; ++k) values[k] = saved_values_[at++];
      MatSeqAIJRestoreArray(local, &values);
    };
    bool factored = false;
    try {
      factored = factor_numeric(factor_.get(), local);
    } catch (...) {
      restore();
      throw;
    }
    restore();
    return factored;
  }

  // First setup, collective: S's sparse pattern from every rank's terms (their places,
  // gathered in rank order), its diagonal always held, and where each gathered term lands.
  void build_schur_pattern(const std::vector<PetscInt>& rows, const std::vector<PetscInt>& columns,
                           std::size_t n_mine) {
    int size = 1;
    MPI_Comm_size(comm_, &size);
    const int mine = static_cast<int>(n_mine);
    term_counts_.assign(static_cast<std::size_t>(size), 0);
    MPI_Allgather(&mine, 1, MPI_INT, term_counts_.data(), 1, MPI_INT, comm_);
    term_offsets_.assign(term_counts_.size(), 0);
    std::partial_sum(term_counts_.begin(), term_counts_.end() - 1, term_offsets_.begin() + 1);
    const auto n_terms = static_cast<std::size_t>(term_offsets_.back() + term_counts_.back());
    std::vector<PetscInt> all_rows(n_terms), all_columns(n_terms);
    MPI_Allgatherv(rows.data(), mine, MPIU_INT, all_rows.data(), term_counts_.data(),
                   term_offsets_.data(), MPIU_INT, comm_);
    MPI_Allgatherv(columns.data(), mine, MPIU_INT, all_columns.data(), term_counts_.data(),
                   term_offsets_.data(), MPIU_INT, comm_);
    const auto n_g = static_cast<PetscInt>(interface_.size());
    std::vector<std::pair<PetscInt, PetscInt>> entries;
    entries.reserve(n_terms + static_cast<std::size_t>(n_g));
    for (std::size_t k = 0; k < n_terms; ++k) entries.emplace_back(all_rows[k], all_columns[k]);
    for (PetscInt i = 0; i < n_g; ++i) entries.emplace_back(i, i);
    std::sort(entries.begin(), entries.end());
    entries.erase(std::unique(entries.begin(), entries.end()), entries.end());
    schur_ia_.assign(static_cast<std::size_t>(n_g) + 1, 0);
    schur_ja_.clear();
    for (const auto& [row, column] : entries) {
      ++schur_ia_[static_cast<std::size_t>(row) + 1];
      schur_ja_.push_back(column);
    }
    std::partial_sum(schur_ia_.begin(), schur_ia_.end(), schur_ia_.begin());
    schur_values_.assign(entries.size(), 0.0);
    term_slot_.resize(n_terms);
    for (std::size_t k = 0; k < n_terms; ++k)
      term_slot_[k] = static_cast<PetscInt>(
          std::lower_bound(entries.begin(), entries.end(), std::pair{all_rows[k], all_columns[k]}) -
          entries.begin());
    all_terms_.resize(n_terms);
    if (schur_constraints_.empty()) {
      CATENA_PETSC(MatCreateSeqAIJWithArrays(PETSC_COMM_SELF, n_g, n_g, schur_ia_.data(),
                                             schur_ja_.data(), schur_values_.data(),
                                             schur_matrix_.out()));
    } else {
      // With multipliers among its rows, S is itself a saddle-point matrix: they go last.
      // Rows of S may share a pattern across that divide (a dense block), which PETSc's LU
      // would factor as one inode that the order splits (a crash in its numeric kernel): S
      // is made without inodes, before its assembly detects them (its own copy of the CSR).
      CATENA_PETSC(MatCreate(PETSC_COMM_SELF, schur_matrix_.out()));
      CATENA_PETSC(MatSetSizes(schur_matrix_.get(), n_g, n_g, n_g, n_g));
      CATENA_PETSC(MatSetType(schur_matrix_.get(), MATSEQAIJ));
      CATENA_PETSC(MatSetOption(schur_matrix_.get(), MAT_USE_INODES, PETSC_FALSE));
      CATENA_PETSC(MatSeqAIJSetPreallocationCSR(schur_matrix_.get(), schur_ia_.data(),
                                                schur_ja_.data(), schur_values_.data()));
      mark_constraint_rows(schur_matrix_.get(), schur_constraints_);
    }
    CATENA_PETSC(
        MatGetFactor(schur_matrix_.get(), MATSOLVERPETSC, MAT_FACTOR_LU, schur_factor_.out()));
    CATENA_PETSC(
        MatGetOrdering(schur_matrix_.get(),
                       schur_constraints_.empty() ? MATORDERINGND : constraints_last_ordering(),
                       schur_row_order_.out(), schur_column_order_.out()));
    const MatFactorInfo info = factor_info();
    CATENA_PETSC(MatLUFactorSymbolic(schur_factor_.get(), schur_matrix_.get(),
                                     schur_row_order_.get(), schur_column_order_.get(), &info));
    CATENA_PETSC(VecCreateSeqWithArray(PETSC_COMM_SELF, 1, n_g, nullptr, r_interface_.out()));
    CATENA_PETSC(VecCreateSeqWithArray(PETSC_COMM_SELF, 1, n_g, nullptr, x_interface_.out()));
  }

  // Collective: every rank's terms gathered, summed into S in the same order on every rank
  // (the same bits, so that every rank takes the same decision), S factored; false on a
  // zero pivot.
  bool assemble_and_factor_schur(const std::vector<PetscScalar>& mine) {
    MPI_Allgatherv(mine.data(), static_cast<int>(mine.size()), MPI_DOUBLE, all_terms_.data(),
                   term_counts_.data(), term_offsets_.data(), MPI_DOUBLE, comm_);
    PetscScalar* s = nullptr;
    CATENA_PETSC(MatSeqAIJGetArray(schur_matrix_.get(), &s));
    std::fill(s, s + schur_values_.size(), 0.0);
    for (std::size_t k = 0; k < all_terms_.size(); ++k) s[term_slot_[k]] += all_terms_[k];
    // PETSc's LU without pivoting compares a pivot with an absolute 100 ε and lets a NaN
    // through: a non-finite S fails here, and the threshold is made relative to S's largest
    // diagonal entry (stiffness-sized: 1e6 and more), as a vanishing pivot is.
    bool finite = true;
    for (std::size_t k = 0; k < schur_values_.size(); ++k) finite = finite && std::isfinite(s[k]);
    double largest = 0.0;
    for (std::size_t i = 0; i + 1 < schur_ia_.size(); ++i)
      for (PetscInt k = schur_ia_[i]; k < schur_ia_[i + 1]; ++k)
        if (schur_ja_[static_cast<std::size_t>(k)] == static_cast<PetscInt>(i))
          largest = std::max(largest, std::abs(s[k]));
    CATENA_PETSC(MatSeqAIJRestoreArray(schur_matrix_.get(), &s));
    if (interface_.empty()) return true;
    if (!finite) return false;
    return factor_numeric(schur_factor_.get(), schur_matrix_.get(), std::max(largest, 1.0));
  }

  // The interface columns (positions) A_IΓ has entries in, ascending.
  static std::vector<Eigen::Index> touched_columns(Mat Aig) {
    PetscInt n_rows = 0, n_columns = 0;
    CATENA_PETSC(MatGetSize(Aig, &n_rows, &n_columns));
    std::vector<char> touched(static_cast<std::size_t>(n_columns), 0);
    for (PetscInt i = 0; i < n_rows; ++i) {
      PetscInt n = 0;
      const PetscInt* c = nullptr;
      CATENA_PETSC(MatGetRow(Aig, i, &n, &c, nullptr));
      for (PetscInt k = 0; k < n; ++k) touched[static_cast<std::size_t>(c[k])] = 1;
      CATENA_PETSC(MatRestoreRow(Aig, i, &n, &c, nullptr));
    }
    std::vector<Eigen::Index> out;
    for (std::size_t k = 0; k < touched.size(); ++k)
      if (touched[k]) out.push_back(static_cast<Eigen::Index>(k));
    return out;
  }

  struct Slots {
    PetscInt begin, end, diagonal;  // places in the diagonal block's value array
  };

  MPI_Comm comm_;
  int rank_ = 0;
  PetscInt first_row_ = 0;                         // this rank's first row, global
  PetscInt n_local_ = 0;                           // this rank's rows
  std::vector<PetscInt> interior_local_;           // this rank's interior rows, local numbers
  std::vector<PetscInt> interface_;                // every rank's interface rows, global, ascending
  std::vector<PetscInt> schur_constraints_;        // the multipliers' places in interface_
  std::vector<PetscInt> owned_local_;              // this rank's interface rows, local numbers
  std::vector<Eigen::Index> owned_position_;       // ... and their places in interface_
  std::vector<Eigen::Index> coupled_position_;     // places of the interface rows in A_CI
  IsHandle interior_, interface_is_, coupled_is_;  // sequential index sets of global rows
  IsHandle local_is_;                              // this rank's rows (global numbers)
  Mat* blocks_ = nullptr;                          // A_IΓ, A_CI
  std::vector<Slots> interface_slots_;             // this rank's interface rows, as Slots
  std::vector<PetscScalar> saved_values_;          // their values while Ã is factored
  MatHandle factor_;                               // Ã's LU
  IsHandle row_order_, column_order_;
  std::vector<Eigen::Index> touched_;
  struct SparseColumn {
    std::vector<PetscInt> rows;  // local, ascending
    std::vector<PetscScalar> values;
  };
  std::vector<SparseColumn> W_;  // A_II⁻¹ A_IΓ's touched columns, their nonzeros
  // S, sparse (CSR arrays PETSc's matrix uses in place), and its LU.
  std::vector<PetscInt> schur_ia_, schur_ja_;
  std::vector<PetscScalar> schur_values_;
  MatHandle schur_matrix_, schur_factor_;
  IsHandle schur_row_order_, schur_column_order_;
  // Every rank's terms of S: counts and offsets per rank, their places in S, the values.
  std::vector<int> term_counts_, term_offsets_;
  std::vector<PetscInt> term_slot_;
  std::vector<PetscScalar> all_terms_;
  PetscObjectState pattern_ = 0;  // A's nonzero state at the first setup
  bool ready_ = false;            // the last setup succeeded
  bool schur_built_ = false;      // S's pattern and symbolic factorisation made
  VecHandle b_local_, y_local_, t_coupled_, r_interface_, x_interface_;
};

InterfaceSchur& context(PC pc) {
  void* c = nullptr;
  CATENA_PETSC(PCShellGetContext(pc, &c));
  return *static_cast<InterfaceSchur*>(c);
}

// A C++ exception must not cross PETSc's C frames: it becomes a PETSc error with its text.
template <class Fn>
PetscErrorCode guarded(PC pc, Fn&& fn) noexcept {
  try {
    fn();
    return 0;
  } catch (const std::exception& e) {
    return PetscError(PetscObjectComm(reinterpret_cast<PetscObject>(pc)), __LINE__,
                      "interface_schur", __FILE__, PETSC_ERR_LIB, PETSC_ERROR_INITIAL, "%s",
                      e.what());
  }
}

PetscErrorCode setup_shell(PC pc) {
  return guarded(pc, [&] {
    // A shell's failure stays set until cleared (PETSc 3.18 clears only its factor PCs').
    CATENA_PETSC(PCSetFailedReason(pc, PC_NOERROR));
    Mat A = nullptr, P = nullptr;
    CATENA_PETSC(PCGetOperators(pc, &A, &P));
    if (!context(pc).setup(P)) CATENA_PETSC(PCSetFailedReason(pc, PC_FACTOR_NUMERIC_ZEROPIVOT));
  });
}

PetscErrorCode apply_shell(PC pc, Vec b, Vec x) {
  return guarded(pc, [&] { context(pc).apply(b, x); });
}

PetscErrorCode destroy_shell(PC pc) {
  return guarded(pc, [&] { delete &context(pc); });
}

}  // namespace

long use_interface_schur(KSP ksp, Mat J) {
  MPI_Comm comm = MPI_COMM_NULL;
  CATENA_PETSC(PetscObjectGetComm(reinterpret_cast<PetscObject>(J), &comm));
  PetscInt first = 0, end = 0;
  CATENA_PETSC(MatGetOwnershipRange(J, &first, &end));
  auto solver = std::make_unique<InterfaceSchur>(comm, split_rows(J), first, end - first);
  const long n_interface = solver->interface_size();
  PC pc = nullptr;
  CATENA_PETSC(KSPGetPC(ksp, &pc));
  CATENA_PETSC(PCSetType(pc, PCSHELL));
  CATENA_PETSC(PCShellSetName(pc, "catena interface Schur complement"));
  CATENA_PETSC(PCShellSetContext(pc, solver.release()));
  CATENA_PETSC(PCShellSetSetUp(pc, setup_shell));
  CATENA_PETSC(PCShellSetApply(pc, apply_shell));
  CATENA_PETSC(PCShellSetDestroy(pc, destroy_shell));
  return n_interface;
}

}  // namespace catena::solvers
