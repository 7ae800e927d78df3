#include "catena/assembly/petsc_call.hpp"

#include <sstream>

namespace catena {

void throw_petsc_error(PetscErrorCode code, const char* expression, const char* file, int line) {
  const char* text = nullptr;
  PetscErrorMessage(code, &text, nullptr);
  std::ostringstream os;
  os << "PETSc error " << static_cast<int>(code) << " (" << (text ? text : "unknown") << ") in "
     << expression << " at " << file << ":" << line;
  throw PetscCallError(code, os.str());
}

void CallbackGuard::rethrow_if_any() {
  if (stored_) {
    std::exception_ptr e = stored_;
    stored_ = nullptr;
    std::rethrow_exception(e);
  }
}

}  // namespace catena
