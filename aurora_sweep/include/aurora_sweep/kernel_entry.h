// The CUDA kernel's per-thread entry, host and device: thread `thread` of
// block `block` (blocks of `block_dim` threads) runs combination first + i,
// i = block * block_dim + thread, into out[i] (over its link when
// `Linked`), and does nothing past n. The
// kernel passes blockIdx.x, blockDim.x and threadIdx.x; a host test calls
// it for every (block, thread) of a launch, so the indexing (64-bit, any
// offset, a last partial block) is tested without a GPU.
#pragma once

#include "aurora_sweep/formation_simulation.h"
#include "aurora_sweep/simulation.h"

namespace aurora_sweep {

// The launch's index of a thread, in 64 bits (a launch may pass 2^31).
AURORA_HD inline long threadIndex(unsigned block, unsigned block_dim, unsigned thread) {
  return static_cast<long>(block) * static_cast<long>(block_dim) + static_cast<long>(thread);
}

template <class Law, typename T, int Capacity, bool Linked = false, bool Predicted = false>
AURORA_HD inline void sweepThread(const SimSetup<typename Law::Vehicle, T>& setup, const GridView& grid, long first, long n,
                                  SimResult* out, unsigned block, unsigned block_dim, unsigned thread) {
  const long i = threadIndex(block, block_dim, thread);
  if (i < n) out[i] = simulateCombination<Law, T, Capacity, Linked, Predicted>(setup, grid, first + i);
}

// The same for a formation sweep (of any shape): one formation per thread
// (with its robots' predictors when `Predicted`).
template <class Law, typename T, int Capacity, bool Linked = false, bool Predicted = false,
          template <typename> class Shape>
AURORA_HD inline void formationThread(const FormationSetup<T, Shape, typename Law::Data>& setup, const GridView& grid, long first, long n,
                                      SimResult* out, unsigned block, unsigned block_dim, unsigned thread) {
  const long i = threadIndex(block, block_dim, thread);
  if (i < n) out[i] = simulateFormation<Law, T, Capacity, Linked, Predicted>(setup, grid, first + i);
}

// Blocks of `block_size` threads that cover n combinations.
inline long blocksFor(long n, int block_size) { return (n + block_size - 1) / block_size; }

}  // namespace aurora_sweep
