#pragma once
// Access to the ghosted local form ([owned | ghosts]) of a PETSc vector, shared by the
// SecondOrderSystem's source files (assembly-internal).
#include <petscvec.h>

#include <type_traits>

#include "catena/assembly/petsc_call.hpp"

namespace catena::assembly::detail {

// The local form for the lifetime of the object; read-only unless Writable.
template <bool Writable>
class LocalArray {
 public:
  using Scalar = std::conditional_t<Writable, PetscScalar, const PetscScalar>;
  explicit LocalArray(Vec ghosted) : ghosted_(ghosted) {
    CATENA_PETSC(VecGhostGetLocalForm(ghosted_, &local_));
    if constexpr (Writable)
      CATENA_PETSC(VecGetArray(local_, &data_));
    else
      CATENA_PETSC(VecGetArrayRead(local_, &data_));
  }
  ~LocalArray() {
    if constexpr (Writable)
      VecRestoreArray(local_, &data_);
    else
      VecRestoreArrayRead(local_, &data_);
    VecGhostRestoreLocalForm(ghosted_, &local_);
  }
  LocalArray(const LocalArray&) = delete;
  LocalArray& operator=(const LocalArray&) = delete;
  Scalar* data() const { return data_; }
  Vec local() const { return local_; }

 private:
  Vec ghosted_;
  Vec local_ = nullptr;
  Scalar* data_ = nullptr;
};
using LocalArrayRead = LocalArray<false>;
using LocalArrayWrite = LocalArray<true>;
}  // namespace catena::assembly::detail
