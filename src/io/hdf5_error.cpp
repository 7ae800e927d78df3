#include "hdf5_error.hpp"

#include <cerrno>
#include <cstring>
#include <string>

#include "catena/core/error.hpp"

namespace catena::io {
namespace {

// HDF5 descriptions may span lines (H5F_open embeds a time stamp with a newline); an
// exception message reads better on one line.
std::string single_line(std::string_view text) {
  std::string line;
  bool pending_space = false;
  for (const char c : text) {
    if (c == '\n' || c == '\r' || c == '\t' || c == ' ') {
      pending_space = !line.empty();
      continue;
    }
    if (pending_space) line += ' ';
    pending_space = false;
    line += c;
  }
  return line;
}

// Walking upward starts at the innermost frame, where the cause was detected (the MPI-IO
// or POSIX error); the outer frames only repeat "unable to create file".
herr_t keep_innermost_description(unsigned depth, const H5E_error2_t* frame, void* out) {
  if (depth == 0 && frame->desc != nullptr) *static_cast<std::string*>(out) = frame->desc;
  return 0;
}

std::string innermost_hdf5_description() {
  std::string description;
  if (H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, keep_innermost_description, &description) < 0 ||
      description.empty())
    return "no further detail from HDF5";
  return single_line(description);
}

}  // namespace

std::string hdf5_failure_message(std::string_view call, std::string_view file,
                                 std::string_view object, int call_errno) {
  std::string message(call);
  message += " failed for '";
  message += file;
  message += "'";
  if (!object.empty()) {
    message += " at ";
    message += object;
  }
  message += ": ";
  if (names_a_write_cause(call_errno))
    message +=
        std::string(std::strerror(call_errno)) + " (HDF5: " + innermost_hdf5_description() + ")";
  else
    message += innermost_hdf5_description();
  H5Eclear2(H5E_DEFAULT);
  return message;
}

bool names_a_write_cause(int error_number) {
  switch (error_number) {
    case ENOSPC:
    case EDQUOT:
    case EIO:
    case EFBIG:
    case EROFS:
    case ESTALE:
      return true;
    default:
      return false;
  }
}

void throw_hdf5_error(std::string_view call, std::string_view file, std::string_view object) {
  throw Error(hdf5_failure_message(call, file, object));
}

hid_t checked_hdf5_id(hid_t id, std::string_view call, std::string_view file,
                      std::string_view object) {
  if (id < 0) throw_hdf5_error(call, file, object);
  return id;
}

void check_hdf5_status(herr_t status, std::string_view call, std::string_view file,
                       std::string_view object) {
  if (status < 0) throw_hdf5_error(call, file, object);
}

Hdf5ErrorPrintingSuppressed::Hdf5ErrorPrintingSuppressed() {
  H5Eget_auto2(H5E_DEFAULT, &previous_handler_, &previous_data_);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

Hdf5ErrorPrintingSuppressed::~Hdf5ErrorPrintingSuppressed() {
  H5Eset_auto2(H5E_DEFAULT, previous_handler_, previous_data_);
}

}  // namespace catena::io
