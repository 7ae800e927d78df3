#include "catena/core/error.hpp"

#include <sstream>

namespace catena {
namespace {
std::string format(const InputLocation& w, const std::string& message) {
  std::ostringstream os;
  if (!w.file.empty()) os << w.file;
  if (w.line > 0) os << ":" << w.line;
  if (!w.file.empty() || w.line > 0) os << ": ";
  if (!w.key.empty()) os << "'" << w.key << "': ";
  os << message;
  return os.str();
}
}  // namespace

InputError::InputError(InputLocation where, const std::string& message)
    : Error(format(where, message)), where_(std::move(where)), message_(message) {}

}  // namespace catena
