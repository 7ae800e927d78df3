#include "catena/assembly/petsc_call.hpp"

#include <cctype>
#include <sstream>
#include <string_view>
#include <utility>
#include <vector>

namespace catena {
namespace {

// The error PETSc raised last, kept by keep_raised_error instead of PETSc's printed
// traceback (a page of configure options a user cannot act on), so that the exception
// carries PETSc's own words: "Unable to find requested PC type foo".
struct RaisedError {
  PetscErrorCode code = 0;
  std::string message;      // at the point of error
  std::string function;     // the routine that raised it
  bool in_options = false;  // raised while reading options: a frame of *SetFromOptions*
                            // or PetscOptions* on the way up
};

RaisedError& raised() {
  static RaisedError error;
  return error;
}
bool handler_pushed = false;  // keep_raised_error is PETSc's handler

PetscErrorCode keep_raised_error(MPI_Comm, int, const char* function, const char*,
                                 PetscErrorCode code, PetscErrorType type, const char* message,
                                 void*) {
  RaisedError& r = raised();
  const std::string_view f = function ? function : "";
  // A chain starts at PETSC_ERROR_INITIAL; a code returned by a callback starts at a
  // repeat frame, whose code tells it from a chain kept earlier.
  if (type == PETSC_ERROR_INITIAL || r.code != code)
    r = RaisedError{code, type == PETSC_ERROR_INITIAL && message ? message : "", std::string(f),
                    false};
  if (f.find("SetFromOptions") != std::string_view::npos || f.starts_with("PetscOptions"))
    r.in_options = true;
  return code;
}

// The options given whose value PETSc's message names ("-hht_pc_type foo" for "Unable to
// find requested PC type foo"), as they were given; empty if none does.
std::string options_named_in(const std::string& message) {
  char* all = nullptr;
  if (PetscOptionsGetAll(nullptr, &all) != 0 || !all) return {};
  std::vector<std::string> tokens;
  std::istringstream in(all);
  for (std::string t; in >> t;) tokens.push_back(t);
  PetscFree(all);
  // A value stands alone: no letter, digit or '_' next to it, and "1" is not in "1.5" or
  // "-1" (a full stop after it ends a sentence unless a digit follows).
  const auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  const auto stands_alone = [&](std::size_t at, std::size_t end) {
    const bool before =
        at == 0 || !(word(message[at - 1]) || message[at - 1] == '.' || message[at - 1] == '-');
    const bool after =
        end == message.size() ||
        !(word(message[end]) || (message[end] == '.' && end + 1 < message.size() &&
                                 std::isdigit(static_cast<unsigned char>(message[end + 1]))));
    return before && after;
  };
  std::string named;
  for (std::size_t i = 0; i + 1 < tokens.size(); ++i) {
    const std::string& value = tokens[i + 1];
    if (tokens[i].size() < 2 || tokens[i][0] != '-' || value[0] == '-') continue;
    for (std::size_t at = message.find(value); at != std::string::npos;
         at = message.find(value, at + 1)) {
      if (stands_alone(at, at + value.size())) {
        named += (named.empty() ? "" : ", ") + tokens[i] + " " + value;
        break;
      }
    }
  }
  return named;
}

}  // namespace

void keep_petsc_errors() {
  // PETSc's debugging options push handlers of their own (abort, attach a debugger) in
  // PetscInitialize: they win.
  for (const char* option : {"-on_error_abort", "-on_error_mpiabort", "-on_error_attach_debugger",
                             "-start_in_debugger", "-on_error_emacs"}) {
    PetscBool set = PETSC_FALSE;
    CATENA_PETSC(PetscOptionsHasName(nullptr, nullptr, option, &set));
    if (set) return;
  }
  CATENA_PETSC(PetscPushErrorHandler(keep_raised_error, nullptr));
  handler_pushed = true;
}

void stop_keeping_petsc_errors() {
  if (!handler_pushed) return;
  PetscPopErrorHandler();
  handler_pushed = false;
  raised() = RaisedError{};
}

void throw_petsc_error(PetscErrorCode code, const char* expression, const char* file, int line) {
  RaisedError r = std::exchange(raised(), RaisedError{});
  if (r.code != code) r = RaisedError{};  // kept from another error
  if (r.in_options) {
    const std::string named = options_named_in(r.message);
    throw InputError({"", 0, named},
                     "PETSc refused " + std::string(named.empty() ? "its options" : "this option") +
                         ": " + r.message + " (in " + r.function +
                         "); `catena --help` lists the solvers' option prefixes, PETSc's manual "
                         "the values each option takes");
  }
  const char* text = nullptr;
  PetscErrorMessage(code, &text, nullptr);
  std::ostringstream os;
  os << "PETSc error " << static_cast<int>(code) << " (" << (text ? text : "unknown") << ")";
  if (!r.message.empty()) os << ": " << r.message << " (raised in " << r.function << ")";
  os << " in " << expression << " at " << file << ":" << line;
  throw PetscCallError(code, os.str());
}

void CallbackGuard::rethrow_if_any() {
  if (stored_) {
    // The code the callback returned went up PETSc's frames as an error: not a chain a
    // later error should be told.
    raised() = RaisedError{};
    std::exception_ptr e = stored_;
    stored_ = nullptr;
    std::rethrow_exception(e);
  }
}

}  // namespace catena
