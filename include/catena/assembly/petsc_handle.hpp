#pragma once
// RAII ownership of PETSc objects (Vec, Mat, KSP, SNES, IS, ...): destroyed on scope exit,
// movable, not copyable. get() hands the raw handle to PETSc calls.
#include <petscksp.h>
#include <petscsnes.h>
#include <petscvec.h>

#include <utility>

namespace catena {

template <class T, PetscErrorCode (*Destroy)(T*)>
class PetscHandle {
 public:
  PetscHandle() = default;
  explicit PetscHandle(T raw) : raw_(raw) {}
  ~PetscHandle() { reset(); }
  PetscHandle(const PetscHandle&) = delete;
  PetscHandle& operator=(const PetscHandle&) = delete;
  PetscHandle(PetscHandle&& o) noexcept : raw_(std::exchange(o.raw_, nullptr)) {}
  PetscHandle& operator=(PetscHandle&& o) noexcept {
    if (this != &o) {
      reset();
      raw_ = std::exchange(o.raw_, nullptr);
    }
    return *this;
  }
  void reset() {
    if (raw_) Destroy(&raw_);  // destructor path: errors cannot be reported
    raw_ = nullptr;
  }
  T get() const { return raw_; }
  T* out() {  // for PETSc creation functions: XCreate(..., handle.out())
    reset();
    return &raw_;
  }
  explicit operator bool() const { return raw_ != nullptr; }

 private:
  T raw_ = nullptr;
};

using VecHandle = PetscHandle<Vec, VecDestroy>;
using MatHandle = PetscHandle<Mat, MatDestroy>;
using KspHandle = PetscHandle<KSP, KSPDestroy>;
using SnesHandle = PetscHandle<SNES, SNESDestroy>;
using IsHandle = PetscHandle<IS, ISDestroy>;

// PetscInitialize/PetscFinalize for the lifetime of main() (or a test binary).
class PetscSession {
 public:
  PetscSession(int* argc, char*** argv, const char* help = nullptr);
  ~PetscSession();
  PetscSession(const PetscSession&) = delete;
  PetscSession& operator=(const PetscSession&) = delete;
};

}  // namespace catena
