#pragma once
// Deterministic data-parallel helpers over the shared thread pool: loops over
// contiguous ranges, and sums whose result does not depend on the thread
// count (fixed blocks, partial sums added in block order).

#include <algorithm>
#include <cstddef>
#include <vector>

#include "core/util/thread_pool.h"

namespace mq::cloth {

// Loops under 2 x this many items run on the calling thread: for a 64 x 64
// sheet, waking the pool for every solver pass costs more than it saves.
constexpr size_t kParallelGrain = 4096;

// Large loops go to the pool in blocks of this many items, claimed by
// whichever thread is free (the caller alone when the worker is late).
constexpr size_t kParallelBlock = 512;

template <class Body>
void forRange(size_t count, Body&& body) {
  if (count < 2 * kParallelGrain) {
    body(size_t(0), count);
    return;
  }
  ThreadPool::shared().parallelBlocks((count + kParallelBlock - 1) / kParallelBlock, [&](size_t block) {
    body(block * kParallelBlock, std::min(count, (block + 1) * kParallelBlock));
  });
}

// Runs body(begin, end) -> double over [0, count) in 64 fixed blocks (in
// parallel when large) and returns the sum of the blocks' results in block
// order: a fused loop + reduction, identical for any thread count.
template <class Body>
double blockReduce(size_t count, Body&& body) {
  constexpr size_t kBlocks = 64, kAlign = 8;
  // Blocks start at multiples of 8 items: the spring product handles eight
  // vertices at once (sliced ELL) and falls back to one at a time elsewhere.
  const size_t block = ((count + kBlocks - 1) / kBlocks + kAlign - 1) / kAlign * kAlign;
  double partial[kBlocks] = {};
  auto run = [&](size_t b) {
    const size_t begin = std::min(count, b * block), end = std::min(count, (b + 1) * block);
    if (begin < end) partial[b] = body(begin, end);
  };
  if (count < 2 * kParallelGrain)
    for (size_t b = 0; b < kBlocks; ++b) run(b);
  else
    ThreadPool::shared().parallelBlocks(kBlocks, run);
  double total = 0.0;
  for (double p : partial) total += p;
  return total;
}

// Sum of term(i) for i in [0, count), in double, identical for any thread count.
template <class Term>
double deterministicSum(size_t count, Term&& term) {
  return blockReduce(count, [&](size_t begin, size_t end) {
    double s = 0.0;
    for (size_t i = begin; i < end; ++i) s += term(i);
    return s;
  });
}

}  // namespace mq::cloth
