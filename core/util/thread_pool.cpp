#include "core/util/thread_pool.h"

#include <algorithm>
#include <chrono>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace mq {

namespace {

// Polls done() for up to kSpinMicroseconds; true when it became true.
template <class Done>
bool spinUntil(Done&& done) {
  using Clock = std::chrono::steady_clock;
  const auto deadline = Clock::now() + std::chrono::microseconds(ThreadPool::kSpinMicroseconds);
  for (;;) {
    for (int k = 0; k < 64; ++k) {
      if (done()) return true;
#if defined(__x86_64__)
      _mm_pause();
#endif
    }
    if (Clock::now() > deadline) return done();
  }
}

}  // namespace

ThreadPool::ThreadPool(unsigned threads) {
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  for (unsigned i = 1; i < threads; ++i) workers_.emplace_back([this, i] { workerLoop(i); });
}

ThreadPool::~ThreadPool() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  for (std::thread& t : workers_) t.join();
}

ThreadPool& ThreadPool::shared() {
  static ThreadPool pool;
  return pool;
}

void ThreadPool::workerLoop(unsigned index) {
  unsigned seen = 0;
  for (;;) {
    std::unique_lock lock(mutex_);
    wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
    if (stopping_) return;
    seen = generation_;
    if (blockJob_) {
      if (!blockJobOpen_) continue;  // the caller already did every block
      ++blockWorkers_;
      const auto* body = blockBody_;
      const size_t count = blockCount_;
      lock.unlock();
      runBlocks(*body, count);
      lock.lock();
      if (--blockWorkers_ == 0) done_.notify_one();
      continue;
    }
    const auto chunk = chunks_[index];
    const auto* body = body_;
    lock.unlock();
    if (chunk.first < chunk.second) (*body)(chunk.first, chunk.second);
    lock.lock();
    if (--pending_ == 0) done_.notify_one();
  }
}

void ThreadPool::runBlocks(const std::function<void(size_t)>& body, size_t count) {
  for (size_t i; (i = nextBlock_.fetch_add(1, std::memory_order_relaxed)) < count;) body(i);
}

void ThreadPool::parallelBlocks(size_t blocks, const std::function<void(size_t)>& body) {
  if (blocks == 0) return;
  if (threadCount() == 1 || blocks == 1) {
    for (size_t i = 0; i < blocks; ++i) body(i);
    return;
  }
  std::lock_guard submitLock(submit_);
  std::unique_lock lock(mutex_);
  blockJob_ = blockJobOpen_ = true;
  blockBody_ = &body;
  blockCount_ = blocks;
  nextBlock_.store(0, std::memory_order_relaxed);
  ++generation_;
  lock.unlock();
  wake_.notify_all();
  runBlocks(body, blocks);
  lock.lock();
  blockJobOpen_ = false;  // a worker waking from now on finds nothing to do
  if (blockWorkers_ != 0) {
    lock.unlock();
    spinUntil([&] { return blockWorkers_.load() == 0; });
    lock.lock();
  }
  done_.wait(lock, [&] { return blockWorkers_ == 0; });
  blockBody_ = nullptr;  // blockJob_ stays set: a late worker must see this job closed
}

void ThreadPool::parallelFor(size_t begin, size_t end, size_t minChunk,
                             const std::function<void(size_t, size_t)>& body) {
  if (end <= begin) return;
  const size_t n = end - begin;
  const unsigned threads = threadCount();
  if (threads == 1 || n < 2 * std::max<size_t>(minChunk, 1)) {
    body(begin, end);
    return;
  }
  const size_t chunk = (n + threads - 1) / threads;
  std::lock_guard submitLock(submit_);
  std::unique_lock lock(mutex_);
  chunks_.assign(threads, {0, 0});
  for (unsigned i = 0; i < threads; ++i) {
    const size_t b = std::min(end, begin + i * chunk);
    chunks_[i] = {b, std::min(end, b + chunk)};
  }
  body_ = &body;
  blockJob_ = false;
  pending_ = threads - 1;
  ++generation_;
  lock.unlock();
  wake_.notify_all();
  body(chunks_[0].first, chunks_[0].second);
  spinUntil([&] { return pending_.load() == 0; });
  lock.lock();
  done_.wait(lock, [&] { return pending_ == 0; });
  body_ = nullptr;
}

}  // namespace mq
