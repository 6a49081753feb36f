#include "core/garment/fabric_color.h"

namespace mq {

glm::vec3 fabricColor(const std::string& fabric) {
  if (fabric == "velvet") return {0.45f, 0.05f, 0.12f};
  if (fabric == "satin") return {0.75f, 0.68f, 0.55f};
  if (fabric == "silk") return {0.8f, 0.75f, 0.9f};
  if (fabric == "wool") return {0.55f, 0.5f, 0.42f};
  if (fabric == "denim") return {0.2f, 0.3f, 0.5f};
  if (fabric == "leather") return {0.35f, 0.2f, 0.1f};
  if (fabric == "rib-knit") return {0.7f, 0.7f, 0.72f};
  return {0.85f, 0.85f, 0.82f};  // cotton
}

}  // namespace mq
