// A save killed at any moment leaves the previous file whole.
#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <random>

#include <sys/wait.h>
#include <unistd.h>

#include "core/util/atomic_file.h"
#include "import_test_util.h"

namespace mq {
namespace {

// Two versions of a large document, told apart by their first byte.
std::string version(char mark) { return std::string(1, mark) + std::string(4 << 20, mark == 'A' ? 'a' : 'b') + "\n"; }

TEST(AtomicFile, WriterKilledAtRandomMomentsNeverLeavesAPartialFile) {
  const std::string path = (test::scratchDir("mq_atomic_kill") / "doc.mqscene").string();
  const std::string a = version('A'), b = version('B');
  writeFileAtomically(path, [&](std::ostream& out) { out << a; });
  std::mt19937 rng(20261204);
  int sawA = 0, sawB = 0;
  for (int round = 0; round < 24; ++round) {
    const pid_t writer = fork();
    ASSERT_GE(writer, 0);
    if (writer == 0) {
      for (int i = 0;; ++i) writeFileAtomically(path, [&](std::ostream& out) { out << (i % 2 ? a : b); });
    }
    usleep(std::uniform_int_distribution<int>(500, 40000)(rng));
    kill(writer, SIGKILL);
    int status = 0;
    waitpid(writer, &status, 0);
    ASSERT_TRUE(WIFSIGNALED(status));
    const std::string now = readFileText(path);
    ASSERT_TRUE(now == a || now == b) << "round " << round << ": a file of " << now.size() << " bytes";
    (now == a ? sawA : sawB)++;
  }
  // Each kill that landed inside a save left its temporary file: the test
  // did hit saves mid-way, not only the moments between them.
  int midSave = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(path).parent_path()))
    midSave += entry.path().filename().string().rfind("doc.mqscene.tmp-", 0) == 0;
  EXPECT_GE(midSave, 1);
  std::cout << "[ kill ] " << midSave << " of 24 kills inside a save; the file held the first version " << sawA
            << " times, the second " << sawB << " times\n";
}

}  // namespace
}  // namespace mq
