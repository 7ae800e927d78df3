#include "catena/solvers/newton/constraints_last_ordering.hpp"

#include <vector>

#include "catena/assembly/petsc_call.hpp"
#include "catena/assembly/petsc_handle.hpp"

namespace catena::solvers {
namespace {

constexpr const char* kName = "catena_constraints_last";
constexpr const char* kMarkedRows = "catena_constraint_rows";

// A PETSc callback (MatOrderingRegister): errors are returned, not thrown.
PetscErrorCode order_constraints_last(Mat mat, MatOrderingType, IS* row, IS* column) {
  PetscFunctionBeginUser;
  PetscObject marked = nullptr;
  PetscCall(PetscObjectQuery(reinterpret_cast<PetscObject>(mat), kMarkedRows, &marked));
  if (!marked)
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_ARG_WRONGSTATE,
            "ordering %s: the matrix's multiplier rows were not marked (mark_constraint_rows)",
            kName);
  IS nested = nullptr, nested_column = nullptr;
  PetscCall(MatGetOrdering(mat, MATORDERINGND, &nested, &nested_column));
  PetscInt n = 0, n_marked = 0;
  PetscCall(ISGetLocalSize(nested, &n));
  std::vector<char> constraint(static_cast<std::size_t>(n), 0);
  IS marked_rows = reinterpret_cast<IS>(marked);
  PetscCall(ISGetLocalSize(marked_rows, &n_marked));
  const PetscInt* rows = nullptr;
  PetscCall(ISGetIndices(marked_rows, &rows));
  for (PetscInt k = 0; k < n_marked; ++k) {
    if (rows[k] < 0 || rows[k] >= n)
      SETERRQ(PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE,
              "ordering %s: marked row %" PetscInt_FMT " outside the matrix's %" PetscInt_FMT
              " rows (a sequential matrix is expected)",
              kName, rows[k], n);
    constraint[static_cast<std::size_t>(rows[k])] = 1;
  }
  PetscCall(ISRestoreIndices(marked_rows, &rows));
  const PetscInt* order = nullptr;
  PetscCall(ISGetIndices(nested, &order));
  std::vector<PetscInt> last_order;
  last_order.reserve(static_cast<std::size_t>(n));
  for (const bool multipliers : {false, true})
    for (PetscInt k = 0; k < n; ++k)
      if ((constraint[static_cast<std::size_t>(order[k])] != 0) == multipliers)
        last_order.push_back(order[k]);
  PetscCall(ISRestoreIndices(nested, &order));
  PetscCall(ISDestroy(&nested));
  PetscCall(ISDestroy(&nested_column));
  PetscCall(ISCreateGeneral(PETSC_COMM_SELF, n, last_order.data(), PETSC_COPY_VALUES, row));
  PetscCall(ISCreateGeneral(PETSC_COMM_SELF, n, last_order.data(), PETSC_COPY_VALUES, column));
  PetscCall(ISSetPermutation(*row));
  PetscCall(ISSetPermutation(*column));
  PetscFunctionReturn(0);
}

}  // namespace

void mark_constraint_rows(Mat J, Vec mask) {
  PetscInt first = 0, n = 0;
  CATENA_PETSC(VecGetOwnershipRange(mask, &first, &n));
  n -= first;
  std::vector<PetscInt> rows;
  const PetscScalar* m = nullptr;
  CATENA_PETSC(VecGetArrayRead(mask, &m));
  for (PetscInt i = 0; i < n; ++i)
    if (m[i] != 0.0) rows.push_back(first + i);
  CATENA_PETSC(VecRestoreArrayRead(mask, &m));
  mark_constraint_rows(J, rows);
}

std::vector<PetscInt> constraint_rows(Mat J) {
  PetscObject marked = nullptr;
  CATENA_PETSC(PetscObjectQuery(reinterpret_cast<PetscObject>(J), kMarkedRows, &marked));
  if (!marked) return {};
  IS rows = reinterpret_cast<IS>(marked);
  PetscInt n = 0;
  CATENA_PETSC(ISGetLocalSize(rows, &n));
  const PetscInt* r = nullptr;
  CATENA_PETSC(ISGetIndices(rows, &r));
  std::vector<PetscInt> out(r, r + n);
  CATENA_PETSC(ISRestoreIndices(rows, &r));
  return out;
}

void mark_constraint_rows(Mat J, const std::vector<PetscInt>& rows) {
  IsHandle marked;
  CATENA_PETSC(ISCreateGeneral(PETSC_COMM_SELF, static_cast<PetscInt>(rows.size()), rows.data(),
                               PETSC_COPY_VALUES, marked.out()));
  // J keeps its own reference.
  CATENA_PETSC(PetscObjectCompose(reinterpret_cast<PetscObject>(J), kMarkedRows,
                                  reinterpret_cast<PetscObject>(marked.get())));
}

const char* constraints_last_ordering() {
  CATENA_PETSC(MatOrderingRegister(kName, order_constraints_last));
  return kName;
}

}  // namespace catena::solvers
