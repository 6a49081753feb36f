#include "sim/cloth/collision/aabb_tree.h"

#include <algorithm>

namespace mq::cloth {

namespace {
constexpr uint32_t kLeafSize = 4;  // a leaf's boxes fill one LeafQuad
}

std::vector<Box> triangleBoxes(const std::vector<glm::vec3>& p, const std::vector<uint32_t>& triangles, float margin) {
  std::vector<Box> boxes(triangles.size() / 3);
  for (size_t t = 0; t < boxes.size(); ++t) {
    Box& b = boxes[t];
    for (int c = 0; c < 3; ++c) b.extend(p[triangles[3 * t + c]]);
    b.min -= glm::vec3(margin);
    b.max += glm::vec3(margin);
  }
  return boxes;
}

float AabbTree::build(const std::vector<Box>& boxes) {
  const uint32_t count = uint32_t(boxes.size());
  order_.resize(count);
  for (uint32_t t = 0; t < count; ++t) order_[t] = t;
  nodes_.clear();
  nodes_.reserve(2 * count / kLeafSize + 2);
  leafQuads_.clear();
  // Twice the boxes' centres, computed once for the median splits' comparisons.
  centres_.resize(count);
  for (uint32_t t = 0; t < count; ++t) centres_[t] = boxes[t].min + boxes[t].max;
  if (count > 0) buildNode(0, count, boxes);
  grandNodes_.clear();
  if (count > 0 && nodes_[0].left >= 0) buildGrandNode(0);
  gatherLeafBoxes(boxes);
  return size();
}

float AabbTree::size() const {
  float sum = 0.0f;
  for (const Node& n : nodes_) sum += n.extent;
  return sum;
}

int32_t AabbTree::buildGrandNode(int32_t node) {
  const int32_t index = int32_t(grandNodes_.size());
  grandNodes_.emplace_back();
  int32_t lanes[4] = {-1, -1, -1, -1};
  int count = 0;
  for (int32_t child : {nodes_[node].left, nodes_[node].right}) {
    if (nodes_[child].left < 0) {
      lanes[count++] = child;
    } else {
      lanes[count++] = nodes_[child].left;
      lanes[count++] = nodes_[child].right;
    }
  }
  for (int k = 0; k < 4; ++k) {
    const int32_t lane = lanes[k];
    const int32_t below = lane >= 0 && nodes_[lane].left >= 0 ? buildGrandNode(lane) : -1;
    grandNodes_[index].node[k] = lane;  // after the recursion: it may move grandNodes_
    grandNodes_[index].below[k] = below;
  }
  return index;
}

void AabbTree::gatherGrandBoxes() {
  for (GrandNode& g : grandNodes_)
    for (int k = 0; k < 4; ++k) {
      const Box b = g.node[k] >= 0 ? nodes_[g.node[k]].box : Box{};
      g.boxes.minX[k] = b.min.x, g.boxes.minY[k] = b.min.y, g.boxes.minZ[k] = b.min.z;
      g.boxes.maxX[k] = b.max.x, g.boxes.maxY[k] = b.max.y, g.boxes.maxZ[k] = b.max.z;
    }
}

void AabbTree::gatherLeafBoxes(const std::vector<Box>& boxes) {
  leafBoxes_.resize(order_.size());
  for (size_t k = 0; k < order_.size(); ++k) leafBoxes_[k] = boxes[order_[k]];
  for (const Node& n : nodes_) {
    if (n.left >= 0) continue;
    LeafQuad& q = leafQuads_[n.quad];
    for (uint32_t k = 0; k < kLeafSize; ++k) {
      const Box b = k < n.count ? leafBoxes_[n.first + k] : Box{};
      q.minX[k] = b.min.x, q.minY[k] = b.min.y, q.minZ[k] = b.min.z;
      q.maxX[k] = b.max.x, q.maxY[k] = b.max.y, q.maxZ[k] = b.max.z;
    }
  }
  gatherGrandBoxes();
}

int32_t AabbTree::buildNode(uint32_t first, uint32_t count, const std::vector<Box>& boxes) {
  const int32_t index = int32_t(nodes_.size());
  nodes_.emplace_back();
  Box box;
  for (uint32_t k = first; k < first + count; ++k) box.extend(boxes[order_[k]]);
  nodes_[index].setBox(box);
  nodes_[index].first = first;
  nodes_[index].count = count;
  if (count <= kLeafSize) {
    nodes_[index].quad = int32_t(leafQuads_.size());
    leafQuads_.emplace_back();
    return index;
  }
  const glm::vec3 extent = box.max - box.min;
  const int axis = extent.x > extent.y ? (extent.x > extent.z ? 0 : 2) : (extent.y > extent.z ? 1 : 2);
  const uint32_t half = count / 2;
  auto centre = [&](uint32_t t) { return centres_[t][axis]; };
  std::nth_element(order_.begin() + first, order_.begin() + first + half, order_.begin() + first + count,
                   [&](uint32_t a, uint32_t b) { return centre(a) < centre(b) || (centre(a) == centre(b) && a < b); });
  const int32_t left = buildNode(first, half, boxes);
  const int32_t right = buildNode(first + half, count - half, boxes);
  nodes_[index].left = left;
  nodes_[index].right = right;
  return index;
}

float AabbTree::refit(const std::vector<Box>& boxes) {
  // Children always follow their parent, so a reverse sweep is bottom-up.
  float sum = 0.0f;
  for (size_t i = nodes_.size(); i-- > 0;) {
    Node& n = nodes_[i];
    Box box;
    if (n.left < 0) {
      for (uint32_t k = n.first; k < n.first + n.count; ++k) box.extend(boxes[order_[k]]);
    } else {
      box = nodes_[n.left].box;
      box.extend(nodes_[n.right].box);
    }
    n.setBox(box);
    sum += n.extent;
  }
  gatherLeafBoxes(boxes);
  return sum;
}

std::vector<AabbTree::PairJob> AabbTree::pairJobs(size_t minJobs,
                                                  const std::function<bool(int32_t)>& skipWithin) const {
  std::vector<PairJob> jobs;
  if (nodes_.empty()) return jobs;
  auto skipped = [&](const PairJob& j) { return j.a == j.b && skipWithin && skipWithin(j.a); };
  jobs.push_back({0, 0});
  // Breadth-first: split every job whose nodes are inner, as pairsWithin()
  // and pairsBetween() would, until there are enough.
  for (bool split = true; split && jobs.size() < minJobs;) {
    split = false;
    std::vector<PairJob> next;
    for (const PairJob& j : jobs) {
      if (skipped(j)) continue;
      const Node &na = nodes_[j.a], &nb = nodes_[j.b];
      if (j.a == j.b && na.left >= 0) {
        next.push_back({na.left, na.left});
        next.push_back({na.right, na.right});
        next.push_back({na.left, na.right});
        split = true;
      } else if (j.a != j.b && na.left >= 0 && nb.left >= 0) {
        if (!na.box.overlaps(nb.box)) continue;
        for (int32_t x : {na.left, na.right})
          for (int32_t y : {nb.left, nb.right}) next.push_back({x, y});
        split = true;
      } else {
        next.push_back(j);
      }
    }
    jobs = std::move(next);
  }
  jobs.erase(std::remove_if(jobs.begin(), jobs.end(), skipped), jobs.end());
  return jobs;
}

}  // namespace mq::cloth
