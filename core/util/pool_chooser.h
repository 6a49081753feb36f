#pragma once
// Chooses, for a job run again and again (the implicit solve of every cloth
// step), whether to run it on the thread pool or on the calling thread alone,
// by timing both. Whether the pool pays depends on the machine at the time:
// a solver iteration's phases meet at barriers, and when the pool's other
// core is busy or slow to wake (another process, a virtual machine's host)
// the caller waits at each of them, and the pool can lose to the caller
// alone (docs/performance.md has the figures). The jobs that use it give the
// same results either way, so the choice changes only the time.
//
// The first two runs time one way each; from then on the faster way is used,
// and every kProbeInterval-th run times the other way again, so a change in
// the machine's load is followed within a few dozen runs.

namespace mq {

class PoolChooser {
 public:
  static constexpr long kProbeInterval = 16;

  // Whether the next run should use the pool.
  bool nextOnPool() const;
  // The last run took `seconds` for `work` units of work (e.g. solver
  // iterations; runs of different sizes are compared per unit).
  void record(bool onPool, double seconds, double work);
  // Seconds per unit of work on the pool (true) or alone (false); 0 until timed.
  double secondsPerUnit(bool onPool) const { return secondsPerUnit_[onPool]; }

 private:
  double secondsPerUnit_[2] = {0.0, 0.0};  // [alone, on the pool], averaged over the last runs
  long runs_ = 0;
};

}  // namespace mq
