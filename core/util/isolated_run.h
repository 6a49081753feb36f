#pragma once
// Runs a piece of third-party code that may crash, hang or exhaust memory on
// a hostile file (Assimp asserts and aborts on some broken files) in a
// forked child with bounded memory and time, so that the caller can refuse
// the file with a message instead of going down with it.

#include <cstddef>
#include <functional>
#include <string>

namespace mq {

struct IsolationLimits {
  size_t memoryBytes = size_t(4) << 30;  // address space of the child (not applied under AddressSanitizer)
  double seconds = 60.0;
};

struct IsolatedOutcome {
  bool ok = false;
  // When not ok: what happened, for a user ("crashed (signal 6, SIGABRT)",
  // "ran out of memory (limit 4 GiB)", "took longer than 60 s").
  std::string problem;
};

// Calls `work` in a child process; `work` returns true for success. A thrown
// std::bad_alloc counts as running out of memory, any other exception as failure.
IsolatedOutcome runIsolated(const std::function<bool()>& work, const IsolationLimits& limits = {});

}  // namespace mq
