#include "sim/cloth/collision/body_feature_contact.h"

#include <algorithm>
#include <cmath>

#ifdef __SSE2__
#include <immintrin.h>
#endif

#include "sim/cloth/collision/proximity.h"
#include "sim/cloth/parallel.h"

namespace mq::cloth {

namespace {

// The gap below which a cloth triangle over a body vertex is in contact, as
// a fraction of the collision thickness, and kept at that. Less than the
// whole thickness: cloth resting on a convex body part at the thickness has
// its triangles' middles a little closer (the chord), and pushing all those
// out every step costs time (10% on the 10k T-shirt) and makes a coarse
// trouser leg ride up. (Pushing only the pierced ones to the whole thickness
// left more T-shirt vertices inside the body.)
constexpr float kGapFraction = 0.5f;
// Pairs up to this many thicknesses beyond the gap are kept too, for
// reapply(): the elongation limit after the contacts moves the cloth by about
// that much, and can draw a triangle that was clear of a body vertex onto it.
constexpr float kReapplyMargin = 1.0f;
// reapply() brings the triangles back to this fraction of the thickness in
// front of the body's vertices only: out of the skin, moving them the least.
constexpr float kReapplyGapFraction = 0.125f;
// Cloth triangles nearly edge-on to the body surface (a fold standing on it)
// have no clear outside: skipped below this |cos| between the normals.
constexpr float kMinAlignment = 0.3f;
// A cloth point behind a body vertex and outside the body, whose nearest
// body surface faces away from the vertex's outside by more than this cos, is
// beyond a thin body part (a hand over a sleeve), not pierced.
constexpr float kBeyond = -0.5f;
constexpr float kMaxShare = 4.0f;
constexpr int kPasses = 4;
constexpr size_t kBlocks = 64;
constexpr size_t kClusterSize = 4;  // body vertices per tree query: the lanes of nearMask()
static_assert(kClusterSize == 4);

// Interleaves the low 10 bits of x with two zero bits between each.
uint32_t spreadBits(uint32_t x) {
  x &= 0x3ff;
  x = (x | (x << 16)) & 0x030000ff;
  x = (x | (x << 8)) & 0x0300f00f;
  x = (x | (x << 4)) & 0x030c30c3;
  x = (x | (x << 2)) & 0x09249249;
  return x;
}

}  // namespace

BodyFeatureContact::BodyFeatureContact(const std::vector<uint32_t>& clothTriangles,
                                       const std::vector<glm::vec3>& restPositions, Search search)
    : search_(search), triangles_(clothTriangles) {
  // A smooth body part can come between cloth vertices that are outside it
  // by about the sagitta of a cloth edge, far less than the edge: half the
  // mean edge length is plenty, and the search (whose cost grows with the
  // square of this depth) stays small on fine cloth.
  double sum = 0.0;
  for (size_t k = 0; k < triangles_.size(); ++k)
    sum += glm::length(restPositions[triangles_[k]] - restPositions[triangles_[k - k % 3 + (k + 1) % 3]]);
  const float meanEdge = triangles_.empty() ? 0.0f : float(sum / double(triangles_.size()));
  maxDepth_ = std::clamp(0.5f * meanEdge, kMinDepth, kMaxDepth);
}

void BodyFeatureContact::prepareBody(const BodyCollider& body) {
  const std::vector<uint32_t>& triangles = body.triangles();
  if (triangles.size() == bodyTriangleCount_ && clusterOrder_.size() == body.positions().size()) return;
  const size_t n = body.positions().size();
  bodyTriangleCount_ = triangles.size();
  // Body vertices in Morton order of the pose now, so each run of
  // kClusterSize is a compact patch (skinning keeps it one) that shares one
  // tree query.
  Box bounds;
  for (const glm::vec3& p : body.positions()) bounds.extend(p);
  const glm::vec3 scale = 1023.0f / glm::max(bounds.max - bounds.min, glm::vec3(1e-6f));
  std::vector<std::pair<uint32_t, uint32_t>> keyed(n);
  for (size_t v = 0; v < n; ++v) {
    const glm::uvec3 cell((body.positions()[v] - bounds.min) * scale);
    keyed[v] = {spreadBits(cell.x) | (spreadBits(cell.y) << 1) | (spreadBits(cell.z) << 2), uint32_t(v)};
  }
  std::sort(keyed.begin(), keyed.end());
  clusterOrder_.resize(n);
  for (size_t k = 0; k < n; ++k) clusterOrder_[k] = keyed[k].second;
  // Each vertex's triangles in increasing order (the order of the normal's sum).
  std::vector<uint32_t> start(n + 1, 0);
  for (uint32_t v : triangles) ++start[v + 1];
  for (size_t v = 0; v < n; ++v) start[v + 1] += start[v];
  std::vector<uint32_t> around(triangles.size());
  std::vector<uint32_t> fill(start.begin(), start.end() - 1);
  for (size_t e = 0; e < triangles.size(); ++e) around[fill[triangles[e]]++] = uint32_t(e / 3);
  ringStart_.assign(1, 0);
  ringCorners_.clear();
  for (const uint32_t v : clusterOrder_) {
    for (uint32_t k = start[v]; k < start[v + 1]; ++k)
      ringCorners_.emplace_back(triangles[3 * around[k]], triangles[3 * around[k] + 1], triangles[3 * around[k] + 2]);
    ringStart_.push_back(uint32_t(ringCorners_.size()));
  }
}

void BodyFeatureContact::updateTriangles(const ClothState& s, float thickness) {
  const size_t count = triangles_.size() / 3;
  planes_.resize(count);
  boxes_.assign(count, Box{});
  std::vector<Box>& boxes = boxes_;
  // Each triangle on its own: in parallel.
  forRange(count, [&](size_t begin, size_t end) {
    for (size_t t = begin; t < end; ++t) {
      const glm::vec3 &a = s.x[triangles_[3 * t]], &b = s.x[triangles_[3 * t + 1]], &c = s.x[triangles_[3 * t + 2]];
      const glm::vec3 normal = glm::cross(b - a, c - a);
      const float length = glm::length(normal);
      Plane& plane = planes_[t];
      plane.normal = length > 0.0f ? normal / length : glm::vec3(0.0f);
      plane.offset = glm::dot(plane.normal, a);
      plane.centroid = (a + b + c) / 3.0f;
      const float r2 =
          std::max({glm::dot(a - plane.centroid, a - plane.centroid), glm::dot(b - plane.centroid, b - plane.centroid),
                    glm::dot(c - plane.centroid, c - plane.centroid)});
      plane.reach = std::sqrt(r2) + thickness;
      boxes[t].extend(a);
      boxes[t].extend(b);
      boxes[t].extend(c);
    }
  });
  if (search_ != Search::Tree) return;
  if (tree_.empty() || tree_.refit(boxes_) > kRebuildGrowth * builtSize_) builtSize_ = tree_.build(boxes_);
}

// The same arithmetic, in the same order, as the scalar tests with glm would
// do (no fused multiply-add on the baseline x86-64), so the same pairs pass.
[[gnu::always_inline]] inline unsigned BodyFeatureContact::nearMask(const float (&run)[3][4], int count,
                                                                    uint32_t t) const {
  const Plane& plane = planes_[t];
  const float ball = plane.reach + maxDepth_;
#ifdef __SSE2__
  const __m128 px = _mm_load_ps(run[0]), py = _mm_load_ps(run[1]), pz = _mm_load_ps(run[2]);
  const __m128 nx = _mm_set1_ps(plane.normal.x), ny = _mm_set1_ps(plane.normal.y), nz = _mm_set1_ps(plane.normal.z);
  const __m128 dx = _mm_sub_ps(px, _mm_set1_ps(plane.centroid.x)), dy = _mm_sub_ps(py, _mm_set1_ps(plane.centroid.y)),
               dz = _mm_sub_ps(pz, _mm_set1_ps(plane.centroid.z));
  auto dot = [](__m128 ax, __m128 ay, __m128 az, __m128 bx, __m128 by, __m128 bz) {
    return _mm_add_ps(_mm_add_ps(_mm_mul_ps(ax, bx), _mm_mul_ps(ay, by)), _mm_mul_ps(az, bz));
  };
  const __m128 inBall = _mm_cmple_ps(dot(dx, dy, dz, dx, dy, dz), _mm_set1_ps(ball * ball));
  const __m128 above = _mm_sub_ps(_mm_set1_ps(plane.offset), dot(nx, ny, nz, px, py, pz));
  const __m128 absAbove = _mm_andnot_ps(_mm_set1_ps(-0.0f), above);
  const __m128 nearPlane = _mm_cmple_ps(absAbove, _mm_set1_ps(maxDepth_));
  const __m128 along = dot(dx, dy, dz, nx, ny, nz);
  const __m128 ix = _mm_sub_ps(dx, _mm_mul_ps(along, nx)), iy = _mm_sub_ps(dy, _mm_mul_ps(along, ny)),
               iz = _mm_sub_ps(dz, _mm_mul_ps(along, nz));
  const __m128 inCircle = _mm_cmple_ps(dot(ix, iy, iz, ix, iy, iz), _mm_set1_ps(plane.reach * plane.reach));
  const unsigned all = unsigned(_mm_movemask_ps(_mm_and_ps(_mm_and_ps(inBall, nearPlane), inCircle)));
  return all & ((1u << count) - 1);
#else
  return nearMaskScalar(run, count, t);
#endif
}

unsigned BodyFeatureContact::nearMaskScalar(const float (&run)[3][4], int count, uint32_t t) const {
  const Plane& plane = planes_[t];
  const float ball = plane.reach + maxDepth_;
  unsigned mask = 0;
  for (int k = 0; k < count; ++k) {
    const glm::vec3 p(run[0][k], run[1][k], run[2][k]);
    const glm::vec3 d = p - plane.centroid;
    if (glm::dot(d, d) > ball * ball) continue;
    if (std::abs(plane.offset - glm::dot(plane.normal, p)) > maxDepth_) continue;
    const glm::vec3 inPlane = d - glm::dot(d, plane.normal) * plane.normal;
    if (glm::dot(inPlane, inPlane) > plane.reach * plane.reach) continue;
    mask |= 1u << k;
  }
  return mask;
}

std::vector<BodyFeatureContact::Contact> BodyFeatureContact::findContacts(const ClothState& s, const BodyCollider& body,
                                                                          float thickness) const {
  const std::vector<glm::vec3>& bodyX = body.positions();
  const float gap = kGapFraction * thickness, keep = gap + kReapplyMargin * thickness;
  // Area-weighted outward unit normal of the body vertex at `place` in clusterOrder_.
  auto outward = [&](size_t place) {
    glm::vec3 sum(0.0f);
    for (uint32_t k = ringStart_[place]; k < ringStart_[place + 1]; ++k) {
      const glm::uvec3& t = ringCorners_[k];
      sum += glm::cross(bodyX[t[1]] - bodyX[t[0]], bodyX[t[2]] - bodyX[t[0]]);
    }
    const float l = glm::length(sum);
    return l > 0.0f ? sum / l : glm::vec3(0.0f);
  };
  const size_t clusters = (bodyX.size() + kClusterSize - 1) / kClusterSize;
  const size_t blockSize = (clusters + kBlocks - 1) / kBlocks;
  std::vector<std::vector<Contact>> blocks(kBlocks);
  auto scan = [&](size_t block) {
    std::vector<Contact>& out = blocks[block];
    // The triangles near some vertex of the run: index << 4 | the vertices' bits.
    std::vector<uint32_t> near;
    for (size_t k = block * blockSize; k < std::min(clusters, (block + 1) * blockSize); ++k) {
      const size_t begin = k * kClusterSize, end = std::min(bodyX.size(), begin + kClusterSize);
      const int count = int(end - begin);
      alignas(16) float run[3][4] = {};
      Box box;
      for (int i = 0; i < count; ++i) {
        const glm::vec3& p = bodyX[clusterOrder_[begin + i]];
        box.extend(p);
        for (int axis = 0; axis < 3; ++axis) run[axis][i] = p[axis];
      }
      box.min -= glm::vec3(maxDepth_);
      box.max += glm::vec3(maxDepth_);
      near.clear();
      if (search_ == Search::Tree) {
        tree_.query(box, [&](uint32_t t) {
          if (const unsigned mask = nearMask(run, count, t)) near.push_back(t << 4 | mask);
        });
      } else {
        for (uint32_t t = 0; t < boxes_.size(); ++t)
          if (boxes_[t].overlaps(box))
            if (const unsigned mask = nearMaskScalar(run, count, t)) near.push_back(t << 4 | mask);
      }
      if (near.empty()) continue;
      std::sort(near.begin(), near.end());  // by triangle: the tree's order depends on the boxes
      for (int i = 0; i < count; ++i) {
        const uint32_t v = clusterOrder_[begin + i];
        const glm::vec3 p = bodyX[v];
        glm::vec3 bodyNormal(0.0f);
        bool normalKnown = false;
        for (const uint32_t entry : near) {
          if (!(entry & (1u << i))) continue;
          // p is within the depth of the triangle's bounding ball, of its
          // plane, and p's foot on the plane within its circle (nearMask()).
          const uint32_t t = entry >> 4;
          const Plane& plane = planes_[t];
          const float above = plane.offset - glm::dot(plane.normal, p);  // the plane seen from p, along its normal
          if (!normalKnown) bodyNormal = outward(begin + i), normalKnown = true;
          const float alignment = glm::dot(plane.normal, bodyNormal);
          if (std::abs(alignment) < kMinAlignment) continue;
          const float side = alignment > 0.0f ? 1.0f : -1.0f;
          const float height = side * above;  // > 0: the triangle is in front of the body vertex
          if (height >= keep || height < -maxDepth_) continue;
          // Only a body vertex under the triangle (not beside it) is in contact.
          const uint32_t a = triangles_[3 * t], b = triangles_[3 * t + 1], c = triangles_[3 * t + 2];
          const glm::vec3 w = closestTriangleWeights(p, s.x[a], s.x[b], s.x[c]);
          const glm::vec3 q = w.x * s.x[a] + w.y * s.x[b] + w.z * s.x[c];
          const glm::vec3 offset = q - p;
          if (glm::length(offset - glm::dot(offset, plane.normal) * plane.normal) > thickness) continue;
          // Behind the body vertex, the triangle's point is inside the body or
          // beside the tip the vertex is (a sharp feature); outside with the
          // body's surface between it and the vertex (the surface facing away
          // from the vertex's side), it is cloth beyond a thin body part. In
          // front (nearly all pairs) no search is needed: the surface under
          // the triangle moves with the body vertex.
          BodyContact contact;
          if (height < 0.0f && body.nearestContact(q, contact, maxDepth_ + thickness) &&
              contact.signedDistance >= 0.0f && glm::dot(contact.normal, side * plane.normal) < kBeyond)
            continue;
          out.push_back({v, t, w, side, body.velocities()[v], height < 0.0f, height < gap});
        }
      }
    }
  };
  if (bodyX.size() < 2 * kParallelGrain)
    for (size_t b = 0; b < kBlocks; ++b) scan(b);
  else
    ThreadPool::shared().parallelBlocks(kBlocks, scan);
  std::vector<Contact> all;
  for (const auto& b : blocks) all.insert(all.end(), b.begin(), b.end());
  return all;
}

// Moves the triangle's point under the body vertex to the gap in front of it
// (the triangle's vertices by weight times inverse mass) and stops its
// approach to the body.
bool BodyFeatureContact::apply(ClothState& s, const BodyCollider& body, const Contact& c, float gap) const {
  const uint32_t v[3] = {triangles_[3 * c.triangle], triangles_[3 * c.triangle + 1], triangles_[3 * c.triangle + 2]};
  const float w[3] = {c.weights.x, c.weights.y, c.weights.z};
  const glm::vec3 faceNormal = glm::cross(s.x[v[1]] - s.x[v[0]], s.x[v[2]] - s.x[v[0]]);
  const float l = glm::length(faceNormal);
  if (!(l > 0.0f)) return false;
  const glm::vec3 n = (c.side / l) * faceNormal;
  glm::vec3 point(0.0f), velocity(0.0f);
  float denom = 0.0f;
  for (int k = 0; k < 3; ++k) {
    point += w[k] * s.x[v[k]];
    velocity += w[k] * s.v[v[k]];
    denom += w[k] * w[k] * s.invMass[v[k]];
  }
  const float height = glm::dot(point - body.positions()[c.bodyVertex], n);
  if (height >= gap || denom <= 0.0f) return false;
  const float push = (gap - height) / denom;
  const float vn = std::min(0.0f, glm::dot(velocity - c.surfaceVelocity, n));
  const float stop = -vn / denom;
  // Next to a pinned (or much heavier) corner, a light one with a small
  // weight would be thrown far: no vertex moves more than kMaxShare times
  // what the point needs (the point then gets there over a few steps).
  for (int k = 0; k < 3; ++k) {
    const float share = w[k] * s.invMass[v[k]];
    s.x[v[k]] += std::min(push * share, kMaxShare * (gap - height)) * n;
    s.v[v[k]] += std::min(stop * share, -kMaxShare * vn) * n;
  }
  return true;
}

int BodyFeatureContact::resolve(ClothState& s, const BodyCollider& body, float thickness, std::vector<uint8_t>& touched,
                                uint8_t nearMark, uint8_t piercedMark) {
  if (body.empty() || triangles_.empty()) return 0;
  prepareBody(body);
  updateTriangles(s, thickness);
  contacts_ = findContacts(s, body, thickness);
  for (int pass = 0; pass < kPasses; ++pass) {
    bool any = false;
    for (const Contact& c : contacts_) {
      if (!apply(s, body, c, kGapFraction * thickness)) continue;
      any = true;
      for (int k = 0; k < 3; ++k) {
        const uint32_t vertex = triangles_[3 * c.triangle + k];
        if (s.invMass[vertex] > 0.0f) touched[vertex] = std::max(touched[vertex], c.pierced ? piercedMark : nearMark);
      }
    }
    if (!any) break;
  }
  return int(std::count_if(contacts_.begin(), contacts_.end(), [](const Contact& c) { return c.withinGap; }));
}

std::vector<BodyFeatureContact::Pair> BodyFeatureContact::lastPairs() const {
  std::vector<Pair> pairs;
  pairs.reserve(contacts_.size());
  for (const Contact& c : contacts_) pairs.push_back({c.bodyVertex, c.triangle, c.pierced, c.withinGap});
  return pairs;
}

int BodyFeatureContact::reapply(ClothState& s, const BodyCollider& body, float thickness,
                                std::vector<uint8_t>& pushed) const {
  int applied = 0;
  for (int pass = 0; pass < kPasses; ++pass) {
    int now = 0;
    for (const Contact& c : contacts_) {
      if (!apply(s, body, c, kReapplyGapFraction * thickness)) continue;
      ++now;
      for (int k = 0; k < 3; ++k) pushed[triangles_[3 * c.triangle + k]] = 1;
    }
    if (now == 0) break;
    applied += now;
  }
  return applied;
}

}  // namespace mq::cloth
