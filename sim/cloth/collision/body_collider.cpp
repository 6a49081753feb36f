#include "sim/cloth/collision/body_collider.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "core/util/error.h"
#include "sim/cloth/collision/proximity.h"
#include "sim/cloth/parallel.h"

namespace mq::cloth {

namespace {

constexpr float kBoxSlack = 1e-5f;  // m: triangle boxes grown by this, against rounding
// m: rounding allowance of the distance bounds of a point's last query
// (positions are exact to ~1e-7 m; a looser bound only means a search).
constexpr float kBoundSlack = 1e-5f;

std::vector<glm::vec3> toVec3(const std::vector<float>& flat) {
  std::vector<glm::vec3> out(flat.size() / 3);
  for (size_t i = 0; i < out.size(); ++i) out[i] = {flat[3 * i], flat[3 * i + 1], flat[3 * i + 2]};
  return out;
}

// For each triangle edge (i, i+1), the other triangle on that edge (-1 on a
// boundary or a non-manifold edge).
std::vector<int32_t> edgeNeighbours(const std::vector<uint32_t>& triangles) {
  std::unordered_map<uint64_t, uint32_t> firstSide;
  firstSide.reserve(triangles.size());
  std::vector<int32_t> neighbour(triangles.size(), -1);
  for (size_t e = 0; e < triangles.size(); ++e) {
    const uint32_t a = triangles[e], b = triangles[e - e % 3 + (e + 1) % 3];
    const uint64_t key = (uint64_t(std::min(a, b)) << 32) | std::max(a, b);
    auto [it, inserted] = firstSide.emplace(key, uint32_t(e));
    if (inserted) continue;
    neighbour[e] = int32_t(it->second / 3);
    neighbour[it->second] = int32_t(e / 3);
  }
  return neighbour;
}

}  // namespace

void BodyCollider::setMesh(const std::vector<float>& positions, const std::vector<uint32_t>& triangles,
                           float searchRadius) {
  const size_t n = positions.size() / 3;
  for (uint32_t t : triangles)
    if (t >= n) throw Error("body mesh triangle index out of range");
  triangles_ = triangles;
  edgeNeighbour_ = edgeNeighbours(triangles_);
  ringStart_.assign(n + 1, 0);
  for (uint32_t v : triangles_) ++ringStart_[v + 1];
  for (size_t v = 0; v < n; ++v) ringStart_[v + 1] += ringStart_[v];
  ringTriangles_.resize(triangles_.size());
  std::vector<uint32_t> fill(ringStart_.begin(), ringStart_.end() - 1);
  for (size_t e = 0; e < triangles_.size(); ++e) ringTriangles_[fill[triangles_[e]]++] = uint32_t(e / 3);
  from_ = to_ = current_ = previous_ = toVec3(positions);
  maxDisplacement_ = maxSpeed_ = 0.0f;
  velocity_.assign(n, glm::vec3(0.0f));
  searchRadius_ = searchRadius;
  tree_.build(triangleBoxes(current_, triangles_, kBoxSlack));
  updateSlotCorners();
  ++pose_;
  ++move_;
  sweptTree_ = tree_;
}

void BodyCollider::setTarget(const std::vector<float>& positions, float frameTime) {
  if (positions.size() != 3 * from_.size()) throw Error("posed body has a different vertex count");
  from_ = current_;
  to_ = toVec3(positions);
  float speed2 = 0.0f;
  for (size_t i = 0; i < to_.size(); ++i) {
    velocity_[i] = frameTime > 0.0f ? (to_[i] - from_[i]) / frameTime : glm::vec3(0.0f);
    speed2 = std::max(speed2, glm::dot(velocity_[i], velocity_[i]));
  }
  maxSpeed_ = std::sqrt(speed2);
}

void BodyCollider::moveTo(float fraction) {
  previous_ = current_;
  float moved2 = 0.0f;
  for (size_t i = 0; i < current_.size(); ++i) {
    current_[i] = from_[i] + fraction * (to_[i] - from_[i]);
    const glm::vec3 d = current_[i] - previous_[i];
    moved2 = std::max(moved2, glm::dot(d, d));
  }
  maxDisplacement_ = std::sqrt(moved2);
  ++move_;
  // Not moved (the step's restart): the boxes and corners are those of
  // tree_ already, and firstHitAlong() takes tree_ for sweptTree_.
  if (moved2 == 0.0f) return;
  ++pose_;
  // nearestContact() needs the triangles' boxes now; firstHitAlong() each
  // box extended by that box moved back by the triangle's mean displacement
  // in this move: it meets a triangle at a point p of it now with
  // p - (1 - s) d on the vertex's segment, so such a box holds every hit.
  // (The swept boxes of a swinging arm are several times the size of its
  // triangles: the nearest-point searches would visit far more of them.)
  std::vector<Box> boxes = triangleBoxes(current_, triangles_, kBoxSlack);
  tree_.refit(boxes);
  updateSlotCorners();
  for (size_t t = 0; t < boxes.size(); ++t) {
    const uint32_t a = triangles_[3 * t], b = triangles_[3 * t + 1], c = triangles_[3 * t + 2];
    const glm::vec3 back =
        (previous_[a] + previous_[b] + previous_[c] - current_[a] - current_[b] - current_[c]) / 3.0f;
    boxes[t].extend(Box{boxes[t].min + back, boxes[t].max + back});
  }
  sweptTree_.refit(boxes);
}

std::vector<float> BodyCollider::flatPositions() const {
  std::vector<float> flat;
  flat.reserve(3 * current_.size());
  for (const glm::vec3& p : current_) flat.insert(flat.end(), {p.x, p.y, p.z});
  return flat;
}

bool BodyCollider::firstHitAlong(const glm::vec3& from, const glm::vec3& to, BodyContact& contact) const {
  const glm::vec3 still = to - from;
  if (glm::dot(still, still) <= 1e-16f && maxDisplacement_ == 0.0f) return false;
  Box box;
  box.extend(from);
  box.extend(to);
  float best = 1.0f;
  bool found = false;
  // Unmoved, the swept boxes would be tree_'s.
  (moved() ? sweptTree_ : tree_).query(box, [&](uint32_t t) {
    const uint32_t ia = triangles_[3 * t], ib = triangles_[3 * t + 1], ic = triangles_[3 * t + 2];
    const glm::vec3 a = current_[ia], b = current_[ib], c = current_[ic];
    // Where the vertex started, seen from the triangle: moved with it.
    const glm::vec3 start = from + (a + b + c - previous_[ia] - previous_[ib] - previous_[ic]) / 3.0f;
    const glm::vec3 dir = to - start;
    const glm::vec3 n = glm::cross(b - a, c - a);
    const float approach = glm::dot(dir, n);
    if (approach >= 0.0f) return;  // only entering through the front side
    const float s = glm::dot(a - start, n) / approach;
    if (s < 0.0f || s >= best) return;
    const glm::vec3 p = start + s * dir;
    if (glm::dot(glm::cross(b - a, p - a), n) < 0.0f || glm::dot(glm::cross(c - b, p - b), n) < 0.0f ||
        glm::dot(glm::cross(a - c, p - c), n) < 0.0f)
      return;
    best = s;
    found = true;
    contact.point = p;
    contact.normal = glm::normalize(n);
    contact.signedDistance = 0.0f;
    contact.velocity = glm::vec3(0.0f);
  });
  return found;
}

glm::vec3 BodyCollider::unitFaceNormal(uint32_t t) const {
  const glm::vec3 &a = current_[triangles_[3 * t]], &b = current_[triangles_[3 * t + 1]],
                  &c = current_[triangles_[3 * t + 2]];
  const glm::vec3 n = glm::cross(b - a, c - a);
  const float length = glm::length(n);
  return length > 0.0f ? n / length : glm::vec3(0.0f);
}

glm::vec3 BodyCollider::pseudoNormal(uint32_t t, const glm::vec3& w) const {
  const int zeros = (w.x == 0.0f) + (w.y == 0.0f) + (w.z == 0.0f);
  if (zeros == 0) return unitFaceNormal(t);
  if (zeros == 1) {
    // The edge opposite the zero weight: (1,2), (2,0) or (0,1) in triangle order.
    const int edge = w.x == 0.0f ? 1 : w.y == 0.0f ? 2 : 0;
    const int32_t across = edgeNeighbour_[3 * t + edge];
    return across < 0 ? unitFaceNormal(t) : unitFaceNormal(t) + unitFaceNormal(uint32_t(across));
  }
  const uint32_t v = triangles_[3 * t + (w.x != 0.0f ? 0 : w.y != 0.0f ? 1 : 2)];
  glm::vec3 sum(0.0f);
  for (uint32_t i = ringStart_[v]; i < ringStart_[v + 1]; ++i) {
    const uint32_t r = ringTriangles_[i];
    const int corner = triangles_[3 * r] == v ? 0 : triangles_[3 * r + 1] == v ? 1 : 2;
    const glm::vec3 p = current_[v];
    const glm::vec3 e1 = current_[triangles_[3 * r + (corner + 1) % 3]] - p;
    const glm::vec3 e2 = current_[triangles_[3 * r + (corner + 2) % 3]] - p;
    const float l1 = glm::length(e1), l2 = glm::length(e2);
    if (l1 <= 0.0f || l2 <= 0.0f) continue;
    const float angle = std::acos(std::clamp(glm::dot(e1, e2) / (l1 * l2), -1.0f, 1.0f));
    sum += angle * unitFaceNormal(r);
  }
  return sum;
}

inline glm::vec3 BodyCollider::velocityAt(uint32_t t, const glm::vec3& w) const {
  return w.x * velocity_[triangles_[3 * t]] + w.y * velocity_[triangles_[3 * t + 1]] +
         w.z * velocity_[triangles_[3 * t + 2]];
}

inline float BodyCollider::considerTriangle(uint32_t t, const glm::vec3& p, Nearest& best) const {
  const uint32_t a = triangles_[3 * t], b = triangles_[3 * t + 1], c = triangles_[3 * t + 2];
  const glm::vec3 w = closestTriangleWeights(p, current_[a], current_[b], current_[c]);
  const glm::vec3 offset = p - (w.x * current_[a] + w.y * current_[b] + w.z * current_[c]);
  const float d2 = glm::dot(offset, offset);
  if (d2 > best.distance2 || (d2 == best.distance2 && (best.triangle < 0 || t > best.triangle))) return d2;
  const glm::vec3 faceNormal = glm::cross(current_[b] - current_[a], current_[c] - current_[a]);
  if (!(glm::dot(faceNormal, faceNormal) > 0.0f)) return d2;
  best = {t, w, d2, best.passed2};
  return d2;
}

void BodyCollider::updateSlotCorners() {
  slotCorners_.resize(tree_.nodeCount());
  for (uint32_t node = 0; node < slotCorners_.size(); ++node)
    for (int slot = 0; slot < 4; ++slot) {
      const int32_t t = tree_.primitiveAt(node, slot);
      if (t < 0) continue;
      for (int corner = 0; corner < 3; ++corner) {
        const glm::vec3& x = current_[triangles_[3 * size_t(t) + corner]];
        for (int axis = 0; axis < 3; ++axis) slotCorners_[node].corner[corner][axis][slot] = x[axis];
      }
    }
}

namespace {

#ifdef MQ_WIDE_TREE_SSE
struct Vec4 {
  __m128 x, y, z;
};
inline Vec4 operator-(const Vec4& a, const Vec4& b) {
  return {_mm_sub_ps(a.x, b.x), _mm_sub_ps(a.y, b.y), _mm_sub_ps(a.z, b.z)};
}
inline __m128 dot(const Vec4& a, const Vec4& b) {
  return _mm_add_ps(_mm_add_ps(_mm_mul_ps(a.x, b.x), _mm_mul_ps(a.y, b.y)), _mm_mul_ps(a.z, b.z));
}
inline Vec4 cross(const Vec4& a, const Vec4& b) {
  return {_mm_sub_ps(_mm_mul_ps(a.y, b.z), _mm_mul_ps(a.z, b.y)),
          _mm_sub_ps(_mm_mul_ps(a.z, b.x), _mm_mul_ps(a.x, b.z)),
          _mm_sub_ps(_mm_mul_ps(a.x, b.y), _mm_mul_ps(a.y, b.x))};
}
// Squared distance from the origin of `from` (p - the segment's start) to the segment along `edge`.
inline __m128 segmentDistance2(const Vec4& from, const Vec4& edge) {
  // A zero-length edge gives 0 / 0: max() takes its second operand for a NaN, so t = 0.
  const __m128 t =
      _mm_min_ps(_mm_max_ps(_mm_div_ps(dot(from, edge), dot(edge, edge)), _mm_setzero_ps()), _mm_set1_ps(1.0f));
  const Vec4 off{_mm_sub_ps(from.x, _mm_mul_ps(t, edge.x)), _mm_sub_ps(from.y, _mm_mul_ps(t, edge.y)),
                 _mm_sub_ps(from.z, _mm_mul_ps(t, edge.z))};
  return dot(off, off);
}
#endif

// A triangle thinner than this (its doubled area squared over its longest
// edge to the fourth, about the sine squared of its smallest angle) gets no
// lower bound (0): the exact closest point of a sliver is too sensitive to
// rounding for the bound's margin.
constexpr float kSliver = 1e-4f;

// Lower bounds of the squared distances from p to the four triangles of a
// node's slots (those of empty slots are meaningless): the distance to the
// plane when p is over the triangle, else to the nearest edge. Exact but for
// rounding; without SSE all 0 (every triangle considered).
void slotLowerBounds(const float (&corner)[3][3][4], const glm::vec3& p, float out[4]) {
#ifdef MQ_WIDE_TREE_SSE
  const Vec4 a{_mm_load_ps(corner[0][0]), _mm_load_ps(corner[0][1]), _mm_load_ps(corner[0][2])};
  const Vec4 b{_mm_load_ps(corner[1][0]), _mm_load_ps(corner[1][1]), _mm_load_ps(corner[1][2])};
  const Vec4 c{_mm_load_ps(corner[2][0]), _mm_load_ps(corner[2][1]), _mm_load_ps(corner[2][2])};
  const Vec4 q{_mm_set1_ps(p.x), _mm_set1_ps(p.y), _mm_set1_ps(p.z)};
  const Vec4 ab = b - a, bc = c - b, ca = a - c, ac = c - a;
  const Vec4 pa = q - a, pb = q - b, pc = q - c;
  const Vec4 n = cross(ab, ac);
  const __m128 n2 = dot(n, n), zero = _mm_setzero_ps();
  // Over the triangle: p left of each edge, seen along the normal.
  const __m128 over =
      _mm_and_ps(_mm_and_ps(_mm_cmpge_ps(dot(cross(ab, pa), n), zero), _mm_cmpge_ps(dot(cross(bc, pb), n), zero)),
                 _mm_cmpge_ps(dot(cross(ca, pc), n), zero));
  const __m128 height = dot(pa, n);
  const __m128 plane2 = _mm_div_ps(_mm_mul_ps(height, height), n2);
  const __m128 edge2 =
      _mm_min_ps(_mm_min_ps(segmentDistance2(pa, ab), segmentDistance2(pb, bc)), segmentDistance2(pc, ca));
  const __m128 longest2 = _mm_max_ps(_mm_max_ps(dot(ab, ab), dot(bc, bc)), dot(ca, ca));
  const __m128 sliver = _mm_cmplt_ps(n2, _mm_mul_ps(_mm_set1_ps(kSliver), _mm_mul_ps(longest2, longest2)));
  const __m128 bound = _mm_or_ps(_mm_and_ps(over, plane2), _mm_andnot_ps(over, edge2));
  _mm_storeu_ps(out, _mm_andnot_ps(sliver, bound));
#else
  (void)corner, (void)p;
  for (int k = 0; k < 4; ++k) out[k] = 0.0f;
#endif
}

}  // namespace

void BodyCollider::considerSlots(uint32_t node, int slots, const glm::vec3& p, Nearest& best) const {
  float lower[4];
  slotLowerBounds(slotCorners_[node].corner, p, lower);
  for (float& l : lower)
    if (!(l >= 0.0f)) l = 0.0f;  // NaN (none expected): considered
  // The bound's margin: the lower bound and the exact distance may each be
  // off by rounding (~1e-7 m).
  auto boundOf = [](float distance2) {
    const float d = std::sqrt(distance2) + kBoundSlack;
    return d * d;
  };
  float bound2 = boundOf(best.distance2);
  while (slots) {
    int k = -1;
    for (int j = 0; j < 4; ++j)
      if ((slots & (1 << j)) && (k < 0 || lower[j] < lower[k])) k = j;
    if (!(lower[k] <= bound2)) {  // the nearest bound's too far: all are
      best.passed2 = std::min(best.passed2, lower[k]);
      return;
    }
    slots &= ~(1 << k);
    const float before = best.distance2;
    const float distance2 = considerTriangle(uint32_t(tree_.primitiveAt(node, k)), p, best);
    best.passed2 = std::min(best.passed2, distance2);
    if (best.distance2 != before) bound2 = boundOf(best.distance2);
  }
}

BodyCollider::Nearest BodyCollider::searchNearest(const glm::vec3& p, float radius, int32_t hint) const {
  // Squared distances only during the search; the contact of the nearest
  // triangle after. Any triangle's distance bounds the nearest one's, so the
  // hint changes what is visited, not the answer.
  Nearest best;
  best.distance2 = radius * radius;
  if (hint >= 0 && size_t(hint) < triangles_.size() / 3) considerTriangle(uint32_t(hint), p, best);
  // Found within the radius already, the search will find one: no lower bound needed.
  float passedInTree2 = 1e30f;
  tree_.nearestByNode(
      p, best.distance2, [&](uint32_t node, int slots) { considerSlots(node, slots, p, best); },
      [&](int32_t node) {
        tree_.prefetchNode(node);
#ifdef MQ_WIDE_TREE_SSE
        const char* corners = reinterpret_cast<const char*>(&slotCorners_[node]);
        for (int line = 0; line < 3; ++line) _mm_prefetch(corners + 64 * line, _MM_HINT_T0);
#endif
      },
      best.triangle < 0 ? &passedInTree2 : nullptr);
  best.passed2 = std::min(best.passed2, passedInTree2);
  return best;
}

bool BodyCollider::nearestContact(const glm::vec3& p, BodyContact& contact, float radius, int32_t hint) const {
  return contactAt(p, searchNearest(p, radius, hint), contact);
}

bool BodyCollider::nearestContact(const glm::vec3& p, BodyContact& contact, float radius, BodyQuery& last) const {
  // From the same point at the same pose: the nearest triangle is the one
  // found (its squared distance decides whether it is within this radius),
  // or none is nearer than the last radius.
  bool within = false;
  if (keptAnswer(last, p, radius, contact, within)) return within;
  ++last.searches;
  const Nearest best = searchNearest(p, radius, last.contact.triangle);
  last.found = contactAt(p, best, last.contact);
  last.clearance = last.found ? 0.0f : std::max(radius, std::sqrt(best.passed2));
  last.distance2 = best.distance2;
  last.weights = best.weights;
  last.pose = pose_;
  last.point = p;
  last.radius = radius;
  if (last.found) contact = last.contact;
  return last.found;
}

bool BodyCollider::keptAnswer(const BodyQuery& last, const glm::vec3& p, float radius, BodyContact& contact,
                              bool& within) const {
  if (last.pose != pose_ || last.point != p || !(last.found || radius <= last.radius)) return false;
  within = last.found && last.distance2 < radius * radius;
  if (!within) return true;
  contact = last.contact;
  // The body's velocity may have changed since (setTarget()), its positions not.
  contact.velocity = velocityAt(uint32_t(contact.triangle), last.weights);
  return true;
}

bool BodyCollider::nearestContactSince(const glm::vec3& p, BodyContact& contact, float radius,
                                       const BodyQuery& last) const {
  if (provesNoneWithin(last, p, radius)) return false;
  bool within = false;
  if (keptAnswer(last, p, radius, contact, within)) return within;
  return nearestContact(p, contact, radius, last.contact.triangle);
}

bool BodyCollider::provesNoneWithin(const BodyQuery& last, const glm::vec3& p, float radius) const {
  if (last.pose != pose_) return false;
  const float nearest =
      last.found ? std::abs(last.contact.signedDistance) : last.clearance;  // from last.point, at least
  return nearest - glm::length(p - last.point) - kBoundSlack > radius;
}

bool BodyCollider::firstHitAlong(const glm::vec3& from, const glm::vec3& to, BodyContact& contact,
                                 BodyQuery& last) const {
  if (last.missMove == move_ && last.missFrom == from && last.missTo == to) return false;
  if (firstHitAlong(from, to, contact)) return true;
  last.missMove = move_;
  last.missFrom = from;
  last.missTo = to;
  return false;
}

bool BodyCollider::contactAt(const glm::vec3& p, const Nearest& best, BodyContact& contact) const {
  if (best.triangle < 0) return false;
  const int64_t nearest = best.triangle;
  const glm::vec3 weights = best.weights;
  const uint32_t a = triangles_[3 * nearest], b = triangles_[3 * nearest + 1], c = triangles_[3 * nearest + 2];
  const glm::vec3 q = weights.x * current_[a] + weights.y * current_[b] + weights.z * current_[c];
  const glm::vec3 side = pseudoNormal(uint32_t(nearest), weights);
  const float d = glm::length(p - q);
  const bool inside = glm::dot(p - q, side) < 0.0f;
  contact.point = q;
  contact.signedDistance = inside ? -d : d;
  // Out of the body is along the shortest way to the surface.
  if (d > 1e-6f)
    contact.normal = inside ? (q - p) / d : (p - q) / d;
  else
    contact.normal = glm::length(side) > 0.0f ? glm::normalize(side) : unitFaceNormal(uint32_t(nearest));
  contact.velocity = velocityAt(uint32_t(nearest), weights);
  contact.triangle = int32_t(nearest);
  return true;
}

}  // namespace mq::cloth
