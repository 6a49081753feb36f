#include <gtest/gtest.h>

#include <atomic>
#include <numeric>
#include <vector>

#include "core/util/thread_pool.h"

namespace {

TEST(ThreadPool, ParallelBlocksRunsEveryBlockExactlyOnce) {
  mq::ThreadPool pool(2);
  std::vector<std::atomic<int>> runs(1000);
  pool.parallelBlocks(runs.size(), [&](size_t b) { runs[b].fetch_add(1); });
  for (size_t b = 0; b < runs.size(); ++b) EXPECT_EQ(runs[b].load(), 1) << "block " << b;
}

TEST(ThreadPool, BlocksAndChunksInterleaveWithoutLosingWork) {
  // Short block jobs closed before the worker wakes, then chunk jobs that
  // need it: a late worker must neither run a closed job nor miss a chunk.
  mq::ThreadPool pool(3);
  for (int round = 0; round < 2000; ++round) {
    std::vector<int> blocks(3, 0);
    pool.parallelBlocks(blocks.size(), [&](size_t b) { blocks[b] += int(b) + 1; });
    EXPECT_EQ(blocks, (std::vector<int>{1, 2, 3}));
    std::vector<int> items(64, 0);
    pool.parallelFor(0, items.size(), 1, [&](size_t b, size_t e) {
      for (size_t i = b; i < e; ++i) items[i] = int(i);
    });
    std::vector<int> expected(64);
    std::iota(expected.begin(), expected.end(), 0);
    ASSERT_EQ(items, expected) << "round " << round;
  }
}

TEST(ThreadPool, SingleThreadPoolRunsBlocksInOrder) {
  mq::ThreadPool pool(1);
  std::vector<size_t> order;
  pool.parallelBlocks(5, [&](size_t b) { order.push_back(b); });
  EXPECT_EQ(order, (std::vector<size_t>{0, 1, 2, 3, 4}));
}

}  // namespace
