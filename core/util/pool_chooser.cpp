#include "core/util/pool_chooser.h"

namespace mq {

bool PoolChooser::nextOnPool() const {
  if (secondsPerUnit_[1] == 0.0) return true;
  if (secondsPerUnit_[0] == 0.0) return false;
  const bool poolFaster = secondsPerUnit_[1] <= secondsPerUnit_[0];
  return runs_ % kProbeInterval == 0 ? !poolFaster : poolFaster;
}

void PoolChooser::record(bool onPool, double seconds, double work) {
  if (!(seconds > 0.0) || !(work > 0.0)) return;
  const double perUnit = seconds / work;
  double& average = secondsPerUnit_[onPool];
  // Half the weight on the last run: one slow run (a page fault, a
  // preemption) does not decide alone, a lasting change shows in two or three.
  average = average == 0.0 ? perUnit : 0.5 * (average + perUnit);
  ++runs_;
}

}  // namespace mq
