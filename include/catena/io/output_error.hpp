#pragma once
// The fourth error tier beside InputError and NumericalError (core/error.hpp): output that
// could not be written (disk full, quota, I/O error). The io layer throws it on every rank
// together, once the ranks have agreed that a write failed on one of them, so that every
// rank unwinds through the same collective cleanup; the message names the file and the
// cause. The app exits with code 4.
#include "catena/core/error.hpp"

namespace catena {

class OutputError : public Error {
 public:
  using Error::Error;
};

}  // namespace catena
