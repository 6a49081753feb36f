#include <gtest/gtest.h>

#include "core/util/pool_chooser.h"

namespace {

// Runs the chooser for `runs` runs of `work` units each, where a unit takes
// `pool` seconds on the pool and `alone` seconds alone; returns how many ran on the pool.
long runOnPool(mq::PoolChooser& chooser, int runs, double pool, double alone, double work = 30.0) {
  long onPool = 0;
  for (int k = 0; k < runs; ++k) {
    const bool usePool = chooser.nextOnPool();
    onPool += usePool;
    chooser.record(usePool, work * (usePool ? pool : alone), work);
  }
  return onPool;
}

TEST(PoolChooser, TimesBothWaysFirst) {
  mq::PoolChooser chooser;
  EXPECT_TRUE(chooser.nextOnPool());
  chooser.record(true, 3.0, 30.0);
  EXPECT_FALSE(chooser.nextOnPool());
  chooser.record(false, 6.0, 30.0);
  EXPECT_DOUBLE_EQ(chooser.secondsPerUnit(true), 0.1);
  EXPECT_DOUBLE_EQ(chooser.secondsPerUnit(false), 0.2);
  EXPECT_TRUE(chooser.nextOnPool());
}

TEST(PoolChooser, KeepsToTheFasterWayProbingTheOtherNowAndThen) {
  mq::PoolChooser pool;
  const long poolRuns = runOnPool(pool, 320, 0.008, 0.012);
  // All but the first alone run and one probe in kProbeInterval.
  EXPECT_GE(poolRuns, 320 - 320 / mq::PoolChooser::kProbeInterval - 1);
  EXPECT_LT(poolRuns, 320);  // the other way is timed again

  mq::PoolChooser alone;
  EXPECT_LE(runOnPool(alone, 320, 0.0148, 0.0118), 320 / mq::PoolChooser::kProbeInterval + 1);
}

TEST(PoolChooser, FollowsAChangeInTheMachinesLoad) {
  mq::PoolChooser chooser;
  runOnPool(chooser, 100, 0.008, 0.012);
  EXPECT_TRUE(chooser.nextOnPool());
  // The other core becomes busy: within a few probes the chooser runs alone.
  runOnPool(chooser, 4 * mq::PoolChooser::kProbeInterval, 0.020, 0.012);
  EXPECT_FALSE(chooser.nextOnPool());
  EXPECT_LE(runOnPool(chooser, 160, 0.020, 0.012), 160 / mq::PoolChooser::kProbeInterval + 1);
}

TEST(PoolChooser, ComparesPerUnitOfWork) {
  mq::PoolChooser chooser;
  chooser.record(true, 2.0, 10.0);   // 0.2 a unit
  chooser.record(false, 3.0, 30.0);  // 0.1 a unit: faster though longer
  EXPECT_FALSE(chooser.nextOnPool());
}

TEST(PoolChooser, IgnoresRunsWithoutTimeOrWork) {
  mq::PoolChooser chooser;
  chooser.record(true, 0.0, 30.0);
  chooser.record(true, 1.0, 0.0);
  EXPECT_EQ(chooser.secondsPerUnit(true), 0.0);
  EXPECT_TRUE(chooser.nextOnPool());
}

}  // namespace
