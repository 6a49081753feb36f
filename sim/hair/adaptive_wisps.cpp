#include "sim/hair/adaptive_wisps.h"

#include <algorithm>
#include <numeric>

#include "core/util/thread_pool.h"
#include "sim/hair/hair_colliders.h"
#include "sim/hair/hair_simulator.h"

namespace mq {

namespace {

glm::vec3 load(const float* a, size_t i) { return {a[3 * i], a[3 * i + 1], a[3 * i + 2]}; }

// Where guide `guide`'s point i is when it follows `leader`: its rest offset
// from the leader's point, turned by the leader's frame there.
glm::vec3 followedPoint(const HairSimulator& sim, int leader, int guide, int i) {
  const size_t n = size_t(sim.pointsPerStrand());
  const size_t l = size_t(leader) * n + size_t(i), g = size_t(guide) * n + size_t(i);
  return load(sim.positions().data(), l) +
         sim.frames()[l] * (load(sim.rest().points.data(), g) - load(sim.rest().points.data(), l));
}

// The rest length of guide g's segment ending at point i.
float restLength(const HairSimulator& sim, int g, int i) {
  const size_t k = size_t(g) * size_t(sim.pointsPerStrand()) + size_t(i);
  return glm::distance(load(sim.rest().points.data(), k), load(sim.rest().points.data(), k - 1));
}

// `to` moved along the line from `from` to lie `length` away from it.
glm::vec3 withLength(const glm::vec3& from, const glm::vec3& to, float length) {
  const glm::vec3 segment = to - from;
  const float current = glm::length(segment);
  return current > 1e-9f ? from + segment * (length / current) : to;
}

}  // namespace

void AdaptiveWisps::build(const HairSimulator& sim, const AdaptiveWispParams& params) {
  params_ = params;
  const size_t guides = sim.strandCount();
  const size_t n = size_t(sim.pointsPerStrand());
  nodes_.clear();
  nodes_.reserve(2 * guides);
  order_.resize(guides);
  std::iota(order_.begin(), order_.end(), 0);
  leafOf_.assign(guides, -1);
  std::vector<glm::vec3> roots(guides);
  for (size_t g = 0; g < guides; ++g) roots[g] = load(sim.rest().points.data(), g * n);
  if (guides > 0) buildNode(0, int(guides), roots);
  positionInOrder_.assign(guides, 0);
  for (size_t k = 0; k < guides; ++k) positionInOrder_[size_t(order_[k])] = int(k);
  inCut_.assign(nodes_.size(), 0);
  for (int leaf : leafOf_) inCut_[size_t(leaf)] = 1;
  pushed_.assign(nodes_.size(), 0.0f);
  rigidTip_.assign(guides, glm::vec3(0.0f));
  measured_ = false;
  swing_.assign(guides, 0.0f);
  time_ = 0.0f;
}

// The guides order_[begin, end) as one node, halved along the longest side of
// their roots' box until single guides remain.
int AdaptiveWisps::buildNode(int begin, int end, const std::vector<glm::vec3>& roots) {
  const int index = int(nodes_.size());
  nodes_.push_back(Node{});
  Node node;
  node.begin = begin;
  node.end = end;
  glm::vec3 centre(0.0f), lo(1e30f), hi(-1e30f);
  for (int k = begin; k < end; ++k) {
    const glm::vec3& r = roots[size_t(order_[k])];
    centre += r;
    lo = glm::min(lo, r);
    hi = glm::max(hi, r);
  }
  centre /= float(end - begin);
  node.nominal = *std::min_element(order_.begin() + begin, order_.begin() + end, [&](int a, int b) {
    return glm::distance(roots[size_t(a)], centre) < glm::distance(roots[size_t(b)], centre);
  });
  node.guide = node.nominal;
  if (end - begin == 1) {
    leafOf_[size_t(order_[begin])] = index;
  } else {
    const glm::vec3 size = hi - lo;
    const int axis = size.x >= size.y && size.x >= size.z ? 0 : (size.y >= size.z ? 1 : 2);
    const int middle = (begin + end) / 2;
    std::nth_element(order_.begin() + begin, order_.begin() + middle, order_.begin() + end,
                     [&](int a, int b) { return roots[size_t(a)][axis] < roots[size_t(b)][axis]; });
    node.first = buildNode(begin, middle, roots);
    node.second = buildNode(middle, end, roots);
  }
  nodes_[size_t(index)] = node;
  return index;
}

void AdaptiveWisps::update(HairSimulator& sim, float dt, const PosedHairColliders* body) {
  if (!built() || sim.strandCount() != leafOf_.size() || !(dt > 0.0f)) return;
  time_ += dt;
  follow(sim, body);
  measureSwing(sim, dt);
  splitWisps(time_);
  mergeWisps(sim, time_);
  applyCut(sim);
}

// Every guide of a wisp but its simulated one follows that one.
void AdaptiveWisps::follow(HairSimulator& sim, const PosedHairColliders* body) {
  const int n = sim.pointsPerStrand();
  ThreadPool::shared().parallelFor(0, cut_.size(), 4, [&](size_t begin, size_t end) {
    thread_local std::vector<glm::vec3> points, velocities;
    thread_local std::vector<float> clearance;
    points.resize(size_t(n));
    velocities.resize(size_t(n));
    clearance.resize(size_t(n));
    for (size_t c = begin; c < end; ++c) {
      const Node& node = nodes_[size_t(cut_[c])];
      float deepest = 0.0f;
      pushed_[size_t(cut_[c])] = 0.0f;
      if (node.end - node.begin < 2) continue;
      // How far each leader point is from the body: a follower point closer
      // to it than that is outside (as children skip the query).
      const float* leader = sim.positions().data() + size_t(node.guide) * n * 3;
      for (int i = 0; i < n; ++i) clearance[size_t(i)] = body ? body->clearance(load(leader, size_t(i))) : 0.0f;
      for (int k = node.begin; k < node.end; ++k) {
        const int g = order_[size_t(k)];
        if (g == node.guide) continue;
        for (int i = 0; i < n; ++i) {
          glm::vec3 p = followedPoint(sim, node.guide, g, i);
          if (i > 0) {
            // The leader's frames turn each point's offset differently where
            // it bends: each segment back to its rest length (follow the
            // leader from the root), then out of the body, then the length
            // again and out once more, so that a follower keeps its length
            // as a simulated guide does.
            const glm::vec3& previous = points[size_t(i - 1)];
            p = withLength(previous, p, restLength(sim, g, i));
            const glm::vec3 unpushed = p;
            glm::vec3 normal;
            const glm::vec3 fromLeader = p - load(leader, size_t(i));
            const bool clear = glm::dot(fromLeader, fromLeader) < clearance[size_t(i)] * clearance[size_t(i)];
            if (body && !clear && body->pushOut(p, normal)) {
              deepest = std::max(deepest, glm::distance(p, unpushed));
              p = withLength(previous, p, restLength(sim, g, i));
              body->pushOut(p, normal);
            }
          }
          points[size_t(i)] = p;
          // The leader's velocity, not the way the point moved: a wisp that
          // just merged moves its followers to where the leader says, and
          // that jump must not become speed when one of them is simulated.
          velocities[size_t(i)] = load(sim.velocities().data(), size_t(node.guide) * n + i);
        }
        sim.placeStrand(size_t(g), points.data(), velocities.data(), sim.frames().data() + size_t(node.guide) * n);
      }
      pushed_[size_t(cut_[c])] = deepest;
    }
  });
}

// How fast each guide's tip moves relative to its root frame: its velocity
// less that of the rest tip carried by the root, the swing that the root's
// motion does not explain.
void AdaptiveWisps::measureSwing(const HairSimulator& sim, float dt) {
  const size_t n = size_t(sim.pointsPerStrand());
  const float* rest = sim.rest().points.data();
  const float* now = sim.positions().data();
  for (size_t g = 0; g < leafOf_.size(); ++g) {
    const size_t root = g * n, tip = root + n - 1;
    const glm::vec3 rigidTip = load(now, root) + sim.frames()[root] * (load(rest, tip) - load(rest, root));
    const glm::vec3 rigidVelocity = measured_ ? (rigidTip - rigidTip_[g]) / dt : glm::vec3(0.0f);
    swing_[g] = glm::distance(load(sim.velocities().data(), tip), rigidVelocity);
    rigidTip_[g] = rigidTip;
  }
  measured_ = true;
}

void AdaptiveWisps::splitWisps(float time) {
  for (int index : cut_) {
    Node& node = nodes_[size_t(index)];
    if (node.first < 0) continue;
    if (swing_[size_t(node.guide)] <= params_.splitSpeed && pushed_[size_t(index)] <= params_.splitContact) continue;
    inCut_[size_t(index)] = 0;
    for (int half : {node.first, node.second}) {
      // The half holding the simulated guide keeps it; the other starts
      // simulating its own from where it followed.
      Node& part = nodes_[size_t(half)];
      part.guide = holds(part, node.guide) ? node.guide : part.nominal;
      inCut_[size_t(half)] = 1;
      pushed_[size_t(half)] = pushed_[size_t(index)];
    }
    node.splitAt = time;
  }
}

bool AdaptiveWisps::holds(const Node& node, int guide) const {
  const int at = positionInOrder_[size_t(guide)];
  return at >= node.begin && at < node.end;
}

bool AdaptiveWisps::followsWithin(const HairSimulator& sim, int leader, int guide, float distance) const {
  const size_t n = size_t(sim.pointsPerStrand());
  for (size_t i = 0; i < n; ++i) {
    const glm::vec3 p = load(sim.positions().data(), size_t(guide) * n + i);
    if (glm::distance(p, followedPoint(sim, leader, guide, int(i))) > distance) return false;
  }
  return true;
}

// Parents whose two halves are in play and move as one take their place
// (one level a step: the candidates are chosen before any merges).
void AdaptiveWisps::mergeWisps(const HairSimulator& sim, float time) {
  const size_t n = size_t(sim.pointsPerStrand());
  const float calm = 0.5f * params_.splitSpeed;
  std::vector<int> merging;
  for (size_t index = 0; index < nodes_.size(); ++index) {
    const Node& node = nodes_[index];
    if (node.first < 0 || inCut_[index] || !inCut_[size_t(node.first)] || !inCut_[size_t(node.second)]) continue;
    if (time - node.splitAt < params_.cooldown) continue;
    const int a = nodes_[size_t(node.first)].guide, b = nodes_[size_t(node.second)].guide;
    if (swing_[size_t(a)] > calm || swing_[size_t(b)] > calm) continue;
    if (std::max(pushed_[size_t(node.first)], pushed_[size_t(node.second)]) > 0.5f * params_.splitContact) continue;
    const glm::vec3 tipVelocityA = load(sim.velocities().data(), size_t(a) * n + n - 1);
    const glm::vec3 tipVelocityB = load(sim.velocities().data(), size_t(b) * n + n - 1);
    if (glm::distance(tipVelocityA, tipVelocityB) > params_.mergeSpeed) continue;
    if (!followsWithin(sim, a, b, params_.mergeDistance)) continue;
    merging.push_back(int(index));
  }
  for (int index : merging) {
    Node& node = nodes_[size_t(index)];
    // The larger half's simulated guide goes on: no guide leaves its path.
    const Node& larger = nodes_[size_t(nodes_[size_t(node.first)].end - nodes_[size_t(node.first)].begin >=
                                               nodes_[size_t(node.second)].end - nodes_[size_t(node.second)].begin
                                           ? node.first
                                           : node.second)];
    node.guide = larger.guide;
    inCut_[size_t(node.first)] = inCut_[size_t(node.second)] = 0;
    inCut_[size_t(index)] = 1;
    pushed_[size_t(index)] = std::max(pushed_[size_t(node.first)], pushed_[size_t(node.second)]);
  }
}

void AdaptiveWisps::applyCut(HairSimulator& sim) {
  cut_.clear();
  std::vector<uint8_t> active(leafOf_.size(), 0);
  for (size_t index = 0; index < nodes_.size(); ++index) {
    if (!inCut_[index]) continue;
    cut_.push_back(int(index));
    active[size_t(nodes_[index].guide)] = 1;
  }
  sim.setActive(std::move(active));
}

}  // namespace mq
