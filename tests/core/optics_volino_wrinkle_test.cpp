// Oracle O25: Volino's wrinkle height.
#include <gtest/gtest.h>

#include "core/optics/volino_wrinkle.h"

namespace mq::optics {
namespace {

TEST(OpticsVolinoWrinkle, EndsMonotoneAndClamped) {
  for (double lambda : {0.0, 0.3, 0.5, 0.8}) {
    EXPECT_EQ(volinoWrinkleHeight(0.0, lambda), 1.0);
    EXPECT_DOUBLE_EQ(volinoWrinkleHeight(1.0, lambda), 1.0 - lambda);
    double previous = 2.0;
    for (double x = 0.0; x <= 4.0; x += 0.01) {
      const double t = volinoWrinkleHeight(x, lambda);
      EXPECT_LE(t, previous);
      EXPECT_GE(t, 0.0);
      EXPECT_LE(t, 1.0);
      previous = t;
    }
  }
  // lambda = 0.8 would give 2*0.8*(1/5 - 1) + 1 = -0.28 at l = 2L: clamped to 0.
  EXPECT_EQ(volinoWrinkleHeight(2.0, 0.8), 0.0);
}

}  // namespace
}  // namespace mq::optics
