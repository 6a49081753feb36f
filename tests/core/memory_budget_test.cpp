// Jobs that would exhaust memory are refused before they allocate.
#include <gtest/gtest.h>

#include <cstdlib>

#include "core/character/default_mannequin.h"
#include "core/hair/character_groom.h"
#include "core/hair/hair_groom.h"
#include "core/util/error.h"
#include "core/util/memory_budget.h"

namespace mq {
namespace {

struct LimitMegabytes {
  explicit LimitMegabytes(const char* megabytes) { setenv("MANNEQUIN_MEMORY_LIMIT_MB", megabytes, 1); }
  ~LimitMegabytes() { unsetenv("MANNEQUIN_MEMORY_LIMIT_MB"); }
};

TEST(MemoryBudget, DefaultAndConfigured) {
  EXPECT_EQ(memoryBudgetBytes(), size_t(8192) << 20);
  LimitMegabytes limit("100");
  EXPECT_EQ(memoryBudgetBytes(), size_t(100) << 20);
  EXPECT_NO_THROW(checkMemoryBudget("small", 50.0 * 1048576));
  try {
    checkMemoryBudget("a bake of 9 frames", 300.0 * 1048576);
    FAIL() << "not refused";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(),
                 "a bake of 9 frames would need about 300 MB (the limit is 100 MB; MANNEQUIN_MEMORY_LIMIT_MB sets it)");
  }
}

TEST(MemoryBudget, GroomRefusesMoreHairThanTheBudget) {
  const Character mannequin = makeDefaultMannequin();
  HairSection section;
  section.style.pointsPerStrand = 1024;
  auto groom = makeSectionGroom(mannequin, section);
  LimitMegabytes limit("64");
  try {
    groom->grow(section.style, 10000);  // 10k x 1024 points: about 625 MB
    FAIL() << "not refused";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("hair: 10000 strands of 1024 points would need about"), std::string::npos)
        << e.what();
  }
  EXPECT_NO_THROW(groom->grow(section.style, 200));
}

}  // namespace
}  // namespace mq
