#include "test_hooks.hpp"

#include <vector>

namespace catena::test {
namespace {
std::vector<std::function<void()>>& hooks() {
  static std::vector<std::function<void()>> h;
  return h;
}
}  // namespace

void register_before_mpi_finalize(std::function<void()> hook) {
  hooks().push_back(std::move(hook));
}

void run_before_mpi_finalize_hooks() {
  for (auto it = hooks().rbegin(); it != hooks().rend(); ++it) (*it)();
  hooks().clear();
}
}  // namespace catena::test
