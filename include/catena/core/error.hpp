#pragma once
// Catena's three error tiers (style.md §6), never mixed:
//  1. Programmer errors: CATENA_ASSERT (debug builds only).
//  2. Bad user input: InputError, always checked, naming file, line, key, value and what
//     is accepted. Thrown on any rank; apps print it once and exit non-zero.
//  3. Expected numerical failure (Newton divergence, singular matrix): NumericalError is
//     raised only after the solver layer has given up (load stepping exhausted etc.).
// PETSc error codes become PetscCallError through the firewall in assembly/petsc_call.hpp.
#include <cassert>
#include <stdexcept>
#include <string>

namespace catena {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Where in the user's input a problem is. Any field may be empty / zero when unknown.
struct InputLocation {
  std::string file;
  int line = 0;     // 1-based; 0 = unknown
  std::string key;  // dotted path, e.g. "elements[3].nodes"
};

class InputError : public Error {
 public:
  InputError(InputLocation where, const std::string& message);
  const InputLocation& where() const { return where_; }
  const std::string& message() const { return message_; }

 private:
  InputLocation where_;
  std::string message_;
};

class NumericalError : public Error {
 public:
  using Error::Error;
};

}  // namespace catena

#ifdef NDEBUG
#define CATENA_ASSERT(cond, msg) ((void)0)
#else
#define CATENA_ASSERT(cond, msg) assert((cond) && (msg))
#endif
