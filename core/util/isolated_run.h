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
  // "ran out of memory (limit 4 GiB)", "took longer than 60 s", "failed").
  std::string problem;
  // When `work` failed ("failed"): the reason it gave, or the exception's message.
  std::string reason;
};

// Calls `work` in a child process; `work` returns true for success, or false
// with a reason, which comes back to the parent (at most 4 KiB of it). A
// thrown std::bad_alloc counts as running out of memory, any other exception
// as failure with its message as the reason.
IsolatedOutcome runIsolated(const std::function<bool(std::string& reason)>& work, const IsolationLimits& limits = {});
IsolatedOutcome runIsolated(const std::function<bool()>& work, const IsolationLimits& limits = {});

}  // namespace mq
