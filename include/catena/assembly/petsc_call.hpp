#pragma once
// The firewall at the PETSc boundary (style.md §7): every PETSc call goes through
// CATENA_PETSC, which turns an error code into a PetscCallError exception carrying PETSc's
// message and the failing expression. Callbacks registered with PETSc must not throw
// through C frames: they use CallbackGuard to store the exception and return an error
// code; the caller rethrows it after the PETSc call returns.
#include <petscsys.h>

#include <exception>
#include <string>

#include "catena/core/error.hpp"

namespace catena {

class PetscCallError : public Error {
 public:
  PetscCallError(PetscErrorCode code, const std::string& what) : Error(what), code_(code) {}
  PetscErrorCode code() const { return code_; }

 private:
  PetscErrorCode code_;
};

// PETSc keeps the error it raises for throw_petsc_error instead of printing its traceback;
// the exception carries PETSc's message. An error raised while PETSc read the options
// given (a bad -PREFIX_pc_type, a number that is not one) becomes an InputError naming the
// option. Called once, after PetscInitialize (PetscSession); not when PETSc's debugging
// options (-on_error_abort, -on_error_attach_debugger, -start_in_debugger, ...) asked for
// their own handler. stop_keeping_petsc_errors() gives PETSc its printing back before
// PetscFinalize, whose errors (an unwritable -log_view file) nobody else would report.
void keep_petsc_errors();
void stop_keeping_petsc_errors();

[[noreturn]] void throw_petsc_error(PetscErrorCode code, const char* expression, const char* file,
                                    int line);

// Holds the first exception thrown inside PETSc callbacks until the solve returns.
class CallbackGuard {
 public:
  // Runs fn(); on exception stores it and returns a nonzero PETSc error code.
  template <class Fn>
  PetscErrorCode run(Fn&& fn) noexcept {
    try {
      fn();
      return 0;
    } catch (...) {
      if (!stored_) stored_ = std::current_exception();
      return PETSC_ERR_USER;
    }
  }
  // Rethrows a stored exception, if any, and clears it.
  void rethrow_if_any();
  bool has_exception() const { return static_cast<bool>(stored_); }

 private:
  std::exception_ptr stored_;
};

}  // namespace catena

#define CATENA_PETSC(expr)                                                                       \
  do {                                                                                           \
    const PetscErrorCode catena_ierr_ = (expr);                                                  \
    if (catena_ierr_ != 0) ::catena::throw_petsc_error(catena_ierr_, #expr, __FILE__, __LINE__); \
  } while (0)
