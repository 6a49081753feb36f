#include "core/optics/volino_wrinkle.h"

#include <algorithm>

namespace mq::optics {

double volinoWrinkleHeight(double compression, double lambda) {
  const double t = 2.0 * lambda * (1.0 / (1.0 + compression * compression) - 1.0) + 1.0;
  return std::clamp(t, 0.0, 1.0);
}

}  // namespace mq::optics
