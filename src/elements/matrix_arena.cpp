#include "catena/elements/matrix_arena.hpp"

#include <algorithm>
#include <new>

namespace catena::elements {
namespace {

constexpr std::size_t kAlignment = 64;                      // bytes: a cache line
constexpr std::size_t kLine = kAlignment / sizeof(double);  // doubles per cache line

}  // namespace

void MatrixArena::Free::operator()(double* p) const {
  ::operator delete[](p, std::align_val_t{kAlignment});
}

MatrixArena::MatrixArena(std::size_t chunk_values)
    : chunk_values_(std::max<std::size_t>(chunk_values, kLine)) {}

double* MatrixArena::allocate(std::size_t n) {
  // Whole cache lines per block, so that every block starts on a line.
  const std::size_t size = (std::max<std::size_t>(n, 1) + kLine - 1) / kLine * kLine;
  if (chunks_.empty() || used_ + size > capacity_) {
    const std::size_t capacity = std::max(chunk_values_, size);
    std::unique_ptr<double[], Free> chunk(static_cast<double*>(
        ::operator new[](capacity * sizeof(double), std::align_val_t{kAlignment})));
    chunks_.push_back(std::move(chunk));  // the arena changes only once both have succeeded
    capacity_ = capacity;
    used_ = 0;
  }
  double* block = chunks_.back().get() + used_;
  used_ += size;
  std::fill(block, block + size, 0.0);
  return block;
}

}  // namespace catena::elements
