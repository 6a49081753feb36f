#pragma once
// Deterministic data-parallel helpers over the shared thread pool: loops over
// contiguous ranges, and sums whose result does not depend on the thread
// count (fixed blocks, partial sums added in block order).

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <functional>
#include <thread>
#include <vector>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

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

// The fixed blocks of blockReduce(): 64 blocks starting at multiples of 8 items.
struct ReduceBlocks {
  static constexpr size_t kCount = 64;
  size_t count, size;
  explicit ReduceBlocks(size_t items)
      : count(items), size(((items + kCount - 1) / kCount + kAlign - 1) / kAlign * kAlign) {}
  size_t begin(size_t b) const { return std::min(count, b * size); }
  size_t end(size_t b) const { return std::min(count, (b + 1) * size); }

 private:
  static constexpr size_t kAlign = 8;
};

// One pool job made of phases that must run in order (a block of a phase
// starts once every block of the phase it depends on is done). Each phase of
// a solver iteration as its own parallel loop would wake the pool worker
// once per phase (tens of microseconds each); here it wakes once per job.
// Blocks are claimed in order, so a block only ever waits for blocks already
// claimed, and run by a thread that does not wait for a later one: no
// deadlock, and results do not depend on which thread runs which block.
class PhasedJob {
 public:
  // Adds a phase of `blocks` blocks calling body(block); `after` is the
  // index of the phase it waits for (-1: none). Returns the phase's index.
  template <class Body>
  int add(size_t blocks, int after, Body&& body) {
    phases_.push_back({blocks, after, std::forward<Body>(body)});
    return int(phases_.size()) - 1;
  }
  // Runs every phase, on the pool when `parallel`, else in order on the caller.
  void run(bool parallel) {
    std::vector<size_t> first(phases_.size() + 1, 0);
    for (size_t k = 0; k < phases_.size(); ++k) first[k + 1] = first[k] + phases_[k].blocks;
    if (!parallel) {
      for (const Phase& phase : phases_)
        for (size_t b = 0; b < phase.blocks; ++b) phase.body(b);
      return;
    }
    std::vector<std::atomic<size_t>> done(phases_.size());
    for (auto& d : done) d.store(0, std::memory_order_relaxed);
    ThreadPool::shared().parallelBlocks(first.back(), [&](size_t index) {
      const size_t k = size_t(std::upper_bound(first.begin(), first.end(), index) - first.begin()) - 1;
      const Phase& phase = phases_[k];
      if (phase.after >= 0) waitFor(done[size_t(phase.after)], phases_[size_t(phase.after)].blocks);
      phase.body(index - first[k]);
      done[k].fetch_add(1, std::memory_order_release);
    });
  }

 private:
  struct Phase {
    size_t blocks;
    int after;
    std::function<void(size_t)> body;
  };
  // The block awaited runs on the other thread right now: spin, and yield
  // now and then in case that thread lost its core.
  static void waitFor(const std::atomic<size_t>& counter, size_t target) {
    for (unsigned spins = 0; counter.load(std::memory_order_acquire) < target; ++spins) {
#if defined(__x86_64__)
      _mm_pause();
#endif
      if (spins % 1024 == 1023) std::this_thread::yield();
    }
  }
  std::vector<Phase> phases_;
};

// Runs body(begin, end) -> double over [0, count) in 64 fixed blocks (in
// parallel when large) and returns the sum of the blocks' results in block
// order: a fused loop + reduction, identical for any thread count.
template <class Body>
double blockReduce(size_t count, Body&& body) {
  // Blocks start at multiples of 8 items: the spring product handles eight
  // vertices at once (sliced ELL) and falls back to one at a time elsewhere.
  const ReduceBlocks blocks(count);
  constexpr size_t kBlocks = ReduceBlocks::kCount;
  double partial[kBlocks] = {};
  auto run = [&](size_t b) {
    const size_t begin = blocks.begin(b), end = blocks.end(b);
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
