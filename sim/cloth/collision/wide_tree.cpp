#include "sim/cloth/collision/wide_tree.h"

#include <algorithm>

namespace mq::cloth {

namespace {

// Splits order[first, first + count) at its middle along the longest axis of
// the primitives' centres; returns the size of the first half.
uint32_t medianSplit(std::vector<uint32_t>& order, uint32_t first, uint32_t count,
                     const std::vector<glm::vec3>& centres) {
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (uint32_t k = first; k < first + count; ++k) {
    lo = glm::min(lo, centres[order[k]]);
    hi = glm::max(hi, centres[order[k]]);
  }
  const glm::vec3 extent = hi - lo;
  const int axis = extent.x > extent.y ? (extent.x > extent.z ? 0 : 2) : (extent.y > extent.z ? 1 : 2);
  const uint32_t half = count / 2;
  std::nth_element(order.begin() + first, order.begin() + first + half, order.begin() + first + count,
                   [&](uint32_t a, uint32_t b) {
                     const float ca = centres[a][axis], cb = centres[b][axis];
                     return ca < cb || (ca == cb && a < b);
                   });
  return half;
}

}  // namespace

float WideTree::build(const std::vector<Box>& boxes) {
  nodes_.clear();
  if (boxes.empty()) return 0.0f;
  std::vector<glm::vec3> centres(boxes.size());
  for (size_t t = 0; t < boxes.size(); ++t) centres[t] = 0.5f * (boxes[t].min + boxes[t].max);
  std::vector<uint32_t> order(boxes.size());
  for (uint32_t t = 0; t < order.size(); ++t) order[t] = t;
  nodes_.reserve(boxes.size() / 2 + 1);
  buildNode(order, 0, uint32_t(order.size()), centres);
  return refit(boxes);
}

int32_t WideTree::buildNode(std::vector<uint32_t>& order, uint32_t first, uint32_t count,
                            const std::vector<glm::vec3>& centres) {
  const int32_t index = int32_t(nodes_.size());
  nodes_.emplace_back();
  // Up to four groups: the primitives themselves, or the quarters of two
  // levels of median splits.
  uint32_t groupFirst[4], groupCount[4];
  int groups = 0;
  if (count <= 4) {
    for (uint32_t k = 0; k < count; ++k) groupFirst[groups] = first + k, groupCount[groups++] = 1;
  } else {
    const uint32_t half = medianSplit(order, first, count, centres);
    for (const auto& [f, c] : {std::pair{first, half}, std::pair{first + half, count - half}}) {
      if (c == 1) {
        groupFirst[groups] = f, groupCount[groups++] = 1;
        continue;
      }
      const uint32_t quarter = medianSplit(order, f, c, centres);
      groupFirst[groups] = f, groupCount[groups++] = quarter;
      groupFirst[groups] = f + quarter, groupCount[groups++] = c - quarter;
    }
  }
  int32_t children[4] = {kNoChild, kNoChild, kNoChild, kNoChild};
  for (int g = 0; g < groups; ++g)
    children[g] =
        groupCount[g] == 1 ? ~int32_t(order[groupFirst[g]]) : buildNode(order, groupFirst[g], groupCount[g], centres);
  Node& node = nodes_[index];
  std::copy(children, children + 4, node.child);
  for (int k = 0; k < 4; ++k) {
    if (children[k] >= 0)
      node.nodeSlots |= 1 << k;
    else if (children[k] != kNoChild)
      node.primitiveSlots |= 1 << k;
  }
  return index;
}

float WideTree::refit(const std::vector<Box>& boxes) {
  float size = 0.0f;
  // Children follow their parent, so a reverse sweep is bottom-up.
  for (size_t i = nodes_.size(); i-- > 0;) {
    Node& n = nodes_[i];
    for (int k = 0; k < 4; ++k) {
      Box b;
      if (n.child[k] >= 0) {
        const Node& c = nodes_[n.child[k]];
        for (int j = 0; j < 4; ++j) b.extend(Box{{c.minX[j], c.minY[j], c.minZ[j]}, {c.maxX[j], c.maxY[j], c.maxZ[j]}});
        const glm::vec3 extent = b.max - b.min;
        size += extent.x + extent.y + extent.z;
      } else if (n.child[k] != kNoChild) {
        b = boxes[uint32_t(~n.child[k])];
      }
      n.minX[k] = b.min.x, n.minY[k] = b.min.y, n.minZ[k] = b.min.z;
      n.maxX[k] = b.max.x, n.maxY[k] = b.max.y, n.maxZ[k] = b.max.z;
    }
  }
  return size;
}

}  // namespace mq::cloth
