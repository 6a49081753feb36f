#include "core/util/isolated_run.h"

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstring>
#include <new>
#include <thread>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#if defined(__SANITIZE_ADDRESS__)
#define MQ_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define MQ_UNDER_ASAN 1
#endif
#endif

namespace mq {
namespace {

std::string gibibytes(size_t bytes) { return std::to_string(bytes >> 30) + " GiB"; }

#ifndef MQ_ISOLATE_IN_PROCESS
// Exit codes of our own, apart from the ones a runtime uses when it stops a
// process (1 from AddressSanitizer, for instance): any other code is a crash.
enum ChildExit { kSucceeded = 0, kFailed = 97, kOutOfMemory = 98 };

constexpr size_t kMaxReason = 4096;

[[noreturn]] void runChild(const std::function<bool(std::string&)>& work, const IsolationLimits& limits,
                           int reasonPipe) {
  // The parent reports what happened; the library's own diagnostics would only repeat it.
  const int devNull = open("/dev/null", O_WRONLY);
  if (devNull >= 0) dup2(devNull, STDERR_FILENO);
#ifndef MQ_UNDER_ASAN
  const rlimit memory{limits.memoryBytes, limits.memoryBytes};
  setrlimit(RLIMIT_AS, &memory);
#else
  (void)limits;
#endif
  int code = kFailed;
  std::string reason;
  try {
    code = work(reason) ? kSucceeded : kFailed;
  } catch (const std::bad_alloc&) {
    code = kOutOfMemory;
  } catch (const std::exception& e) {
    reason = e.what();
  } catch (...) {
  }
  // Within a pipe's buffer: the write never waits for the parent.
  if (code == kFailed && !reason.empty()) (void)!write(reasonPipe, reason.data(), std::min(reason.size(), kMaxReason));
  _exit(code);  // no atexit handlers or static destructors of the parent's state
}

// Waits for the child within the time limit and says how it ended.
IsolatedOutcome waitForChild(pid_t child, const IsolationLimits& limits) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(limits.seconds);
  int status = 0;
  auto pause = std::chrono::microseconds(200);
  for (;;) {
    const pid_t done = waitpid(child, &status, WNOHANG);
    if (done == child) break;
    if (done < 0 && errno != EINTR)
      return {false, std::string("lost the reading process: ") + std::strerror(errno), ""};
    if (std::chrono::steady_clock::now() > deadline) {
      kill(child, SIGKILL);
      waitpid(child, &status, 0);
      return {false, "took longer than " + std::to_string(int(limits.seconds)) + " s", ""};
    }
    std::this_thread::sleep_for(pause);
    pause = std::min(pause * 2, std::chrono::microseconds(20000));
  }
  if (WIFSIGNALED(status)) {
    const int signal = WTERMSIG(status);
    const char* name = sigabbrev_np(signal);
    return {false, "crashed (signal " + std::to_string(signal) + (name ? std::string(", SIG") + name : "") + ")", ""};
  }
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : kFailed;
  if (code == kSucceeded) return {true, "", ""};
  if (code == kOutOfMemory) return {false, "ran out of memory (limit " + gibibytes(limits.memoryBytes) + ")", ""};
  if (code == kFailed) return {false, "failed", ""};
  return {false, "crashed (exit code " + std::to_string(code) + ")", ""};
}

#endif

}  // namespace

#ifdef MQ_ISOLATE_IN_PROCESS
// The fuzzing build (core/CMakeLists.txt): the fuzzer's own processes stand in for the child.
IsolatedOutcome runIsolated(const std::function<bool(std::string&)>& work, const IsolationLimits& limits) {
  std::string reason;
  try {
    return work(reason) ? IsolatedOutcome{true, "", ""} : IsolatedOutcome{false, "failed", reason};
  } catch (const std::bad_alloc&) {
    return {false, "ran out of memory (limit " + gibibytes(limits.memoryBytes) + ")", ""};
  } catch (const std::exception& e) {
    return {false, "failed", e.what()};
  } catch (...) {
    return {false, "failed", ""};
  }
}
#else
IsolatedOutcome runIsolated(const std::function<bool(std::string&)>& work, const IsolationLimits& limits) {
  int reasonPipe[2];
  if (pipe2(reasonPipe, O_CLOEXEC | O_NONBLOCK) != 0)
    return {false, std::string("cannot open a pipe: ") + std::strerror(errno), ""};
  const pid_t child = fork();
  if (child < 0) {
    close(reasonPipe[0]), close(reasonPipe[1]);
    return {false, std::string("cannot start a process: ") + std::strerror(errno), ""};
  }
  if (child == 0) runChild(work, limits, reasonPipe[1]);
  close(reasonPipe[1]);
  IsolatedOutcome outcome = waitForChild(child, limits);
  char buffer[kMaxReason];
  const ssize_t got = read(reasonPipe[0], buffer, sizeof buffer);
  close(reasonPipe[0]);
  if (!outcome.ok && outcome.problem == "failed" && got > 0) outcome.reason.assign(buffer, size_t(got));
  return outcome;
}
#endif

IsolatedOutcome runIsolated(const std::function<bool()>& work, const IsolationLimits& limits) {
  return runIsolated([&work](std::string&) { return work(); }, limits);
}

}  // namespace mq
