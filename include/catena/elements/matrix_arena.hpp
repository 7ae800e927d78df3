#pragma once
// Contiguous storage for the constant matrices that elements keep (Rayleigh damping's D),
// handed out in the order the elements are built, which is the order the residual's loop
// visits them: a pass over the elements then reads one address stream that the hardware
// prefetcher follows, where a heap block per element (between the element's other
// allocations and the holes its construction's temporaries left) breaks the stream and
// leaves every matrix to a cache miss. Measured: docs/performance.md, "EN 50318 reference
// case" (the damping product of an HHT residual).
//
// Blocks are 64-byte aligned (a 12 × 12 matrix is then exactly 18 cache lines) and never
// move; the arena frees them all when it goes. Not thread-safe; elements that took storage
// keep the arena alive (shared ownership).
#include <cstddef>
#include <memory>
#include <vector>

namespace catena::elements {

class MatrixArena {
 public:
  // Chunks of `chunk_values` doubles (a matrix larger than that gets a chunk of its own).
  explicit MatrixArena(std::size_t chunk_values = std::size_t{1} << 16);
  MatrixArena(const MatrixArena&) = delete;
  MatrixArena& operator=(const MatrixArena&) = delete;

  // n doubles, zeroed, 64-byte aligned, contiguous with the previous block when they fit in
  // the current chunk.
  double* allocate(std::size_t n);

  std::size_t chunks() const { return chunks_.size(); }

 private:
  struct Free {
    void operator()(double* p) const;
  };
  std::size_t chunk_values_;
  std::vector<std::unique_ptr<double[], Free>> chunks_;
  std::size_t used_ = 0, capacity_ = 0;  // of the last chunk, in doubles
};

}  // namespace catena::elements
