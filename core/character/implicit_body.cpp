#include "core/character/implicit_body.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "core/util/thread_pool.h"

namespace mq {
namespace {

// Inigo Quilez's exact distance to a round cone from a = 0 to b = (0, L, 0).
float roundConeDistance(const glm::vec3& p, float length, float r1, float r2) {
  const glm::vec3 ba(0.0f, length, 0.0f);
  const float l2 = length * length;
  const float rr = r1 - r2;
  const float a2 = l2 - rr * rr;
  const float il2 = 1.0f / l2;
  const float y = glm::dot(p, ba);
  const float z = y - l2;
  const glm::vec3 w = p * l2 - ba * y;
  const float x2 = glm::dot(w, w);
  const float y2 = y * y * l2;
  const float z2 = z * z * l2;
  const float k = (rr > 0.0f ? 1.0f : (rr < 0.0f ? -1.0f : 0.0f)) * rr * rr * x2;
  if ((z > 0.0f ? 1.0f : -1.0f) * a2 * z2 > k) return std::sqrt(x2 + z2) * il2 - r2;
  if ((y > 0.0f ? 1.0f : -1.0f) * a2 * y2 < k) return std::sqrt(x2 + y2) * il2 - r1;
  return (std::sqrt(x2 * a2 * il2) + y * rr) * il2 - r1;
}

// A bound of the distance to an ellipsoid centred at 0 (Quilez), exact on it.
float ellipsoidDistance(const glm::vec3& p, const glm::vec3& r) {
  const float k0 = glm::length(p / r);
  const float k1 = glm::length(p / (r * r));
  if (k1 < 1e-12f) return -std::min(r.x, std::min(r.y, r.z));
  return k0 * (k0 - 1.0f) / k1;
}

// Polynomial smooth minimum with a small rounding k (distances in units of
// blend): softens the creases where a group's members meet while bulging
// at most k / 4 there.
float smoothMin(float a, float b) {
  constexpr float k = 0.3f;
  const float h = std::max(k - std::abs(a - b), 0.0f) / k;
  return std::min(a, b) - h * h * k * 0.25f;
}

// Polynomial smooth maximum with rounding radius k.
float smoothMax(float a, float b, float k) {
  const float h = std::max(k - std::abs(a - b), 0.0f) / k;
  return std::max(a, b) + h * h * k * 0.25f;
}

// An orthonormal frame whose rows are (x, y, z) with y along `axis` and x
// along `wide` made perpendicular to it.
glm::mat3 frameAlong(const glm::vec3& axis, glm::vec3 wide) {
  const glm::vec3 y = glm::normalize(axis);
  wide -= glm::dot(wide, y) * y;
  if (glm::length(wide) < 1e-6f) {
    wide = std::abs(y.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1);
    wide -= glm::dot(wide, y) * y;
  }
  const glm::vec3 x = glm::normalize(wide);
  const glm::vec3 z = glm::cross(x, y);
  return glm::transpose(glm::mat3(x, y, z));  // rows: world -> local
}

// The box around `box` rotated and translated (Arvo: each output axis sums
// the extremes of the rotated input axes).
Aabb movedBox(const Aabb& box, const glm::mat3& rotation, const glm::vec3& translation) {
  Aabb out;
  out.min = out.max = translation;
  for (int axis = 0; axis < 3; ++axis)
    for (int k = 0; k < 3; ++k) {
      const float a = rotation[k][axis] * box.min[k], b = rotation[k][axis] * box.max[k];
      out.min[axis] += std::min(a, b);
      out.max[axis] += std::max(a, b);
    }
  return out;
}

}  // namespace

ImplicitPrimitive ImplicitPrimitive::roundCone(const glm::vec3& a, const glm::vec3& b, float r0, float r1, int bone,
                                               float blend, const glm::vec3& wide, float wideScale, float thickScale) {
  ImplicitPrimitive p;
  p.shape = Shape::RoundCone;
  p.bone = bone;
  p.blend = blend;
  p.origin = a;
  p.localFromWorld = frameAlong(b - a, wide);
  p.stretch = {wideScale, 1.0f, thickScale};
  p.length = glm::distance(a, b);
  p.radius0 = r0;
  p.radius1 = r1;
  const float radius = std::max(r0, r1) * std::max({wideScale, thickScale, 1.0f});
  p.extent.extend(glm::min(a, b) - glm::vec3(radius));
  p.extent.extend(glm::max(a, b) + glm::vec3(radius));
  p.support = p.extent;
  p.support.extend(p.extent.min - glm::vec3(ImplicitBody::kCutoff * blend));
  p.support.extend(p.extent.max + glm::vec3(ImplicitBody::kCutoff * blend));
  return p;
}

ImplicitPrimitive ImplicitPrimitive::ellipsoid(const glm::vec3& center, const glm::vec3& radii, int bone, float blend) {
  ImplicitPrimitive p;
  p.shape = Shape::Ellipsoid;
  p.bone = bone;
  p.blend = blend;
  p.origin = center;
  p.radii = radii;
  p.extent.extend(center - radii);
  p.extent.extend(center + radii);
  const glm::vec3 reach = radii + glm::vec3(ImplicitBody::kCutoff * blend);
  p.support.extend(center - reach);
  p.support.extend(center + reach);
  return p;
}

float ImplicitPrimitive::distance(const glm::vec3& p) const {
  const glm::vec3 local = localFromWorld * (p - origin);
  if (shape == Shape::Ellipsoid) return ellipsoidDistance(local, radii);
  const float shrink = std::min({stretch.x, stretch.y, stretch.z});
  return roundConeDistance(local / stretch, length, radius0, radius1) * shrink;
}

void ImplicitBody::add(const ImplicitPrimitive& primitive) {
  if (primitive.group >= kMaxGroups) throw std::invalid_argument("ImplicitBody: primitive group out of range");
  primitives_.push_back(primitive);
}

Aabb ImplicitBody::bounds() const {
  Aabb box;
  for (const ImplicitPrimitive& p : primitives_) {
    box.extend(p.support.min);
    box.extend(p.support.max);
  }
  return box;
}

float ImplicitBody::valueFrom(const glm::vec3& p, const int* candidates, size_t count) const {
  float sum = 0.0f;
  float groupNearest[kMaxGroups];
  std::fill(groupNearest, groupNearest + kMaxGroups, kCutoff);
  for (size_t c = 0; c < count; ++c) {
    const ImplicitPrimitive& prim = primitives_[candidates[c]];
    const float x = prim.distance(p) / prim.blend;
    if (prim.group >= 0)
      groupNearest[prim.group] = smoothMin(groupNearest[prim.group], x);
    else if (x < kCutoff)
      sum += std::exp(-x);
  }
  for (float x : groupNearest)
    if (x < kCutoff) sum += std::exp(-x);
  const float farAway = kCutoff * referenceBlend_;
  float v = sum > 0.0f ? std::min(-referenceBlend_ * std::log(sum), farAway) : farAway;
  if (hasGround_) v = smoothMax(v, groundHeight_ - p.y, groundRounding_);
  return v;
}

void ImplicitBody::candidatesAt(const glm::vec3& p, std::vector<int>& out) const {
  out.clear();
  for (size_t i = 0; i < primitives_.size(); ++i) {
    const Aabb& s = primitives_[i].support;
    if (glm::all(glm::lessThanEqual(s.min, p)) && glm::all(glm::lessThanEqual(p, s.max))) out.push_back(int(i));
  }
}

float ImplicitBody::value(const glm::vec3& p) const {
  static thread_local std::vector<int> near;
  candidatesAt(p, near);
  return valueFrom(p, near.data(), near.size());
}

ImplicitBody ImplicitBody::posed(const std::vector<glm::mat4>& worldFromBind) const {
  ImplicitBody out;
  out.referenceBlend_ = referenceBlend_;
  out.primitives_ = primitives_;
  for (ImplicitPrimitive& prim : out.primitives_) {
    if (prim.bone < 0 || prim.bone >= static_cast<int>(worldFromBind.size())) continue;
    const glm::mat4& m = worldFromBind[prim.bone];
    const glm::mat3 rotation(glm::normalize(glm::vec3(m[0])), glm::normalize(glm::vec3(m[1])),
                             glm::normalize(glm::vec3(m[2])));
    const glm::vec3 translation(m[3]);
    prim.origin = rotation * prim.origin + translation;
    prim.localFromWorld = prim.localFromWorld * glm::transpose(rotation);
    prim.extent = movedBox(prim.extent, rotation, translation);
    prim.support = movedBox(prim.support, rotation, translation);
  }
  return out;
}

void ImplicitBody::scale(float factor) {
  for (ImplicitPrimitive& prim : primitives_) {
    prim.origin *= factor;
    prim.length *= factor;
    prim.radius0 *= factor;
    prim.radius1 *= factor;
    prim.radii *= factor;
    prim.blend *= factor;
    prim.extent = {prim.extent.min * factor, prim.extent.max * factor};
    prim.support = {prim.support.min * factor, prim.support.max * factor};
  }
  referenceBlend_ *= factor;
  groundHeight_ *= factor;
  groundRounding_ *= factor;
}

glm::vec3 ImplicitBody::normal(const glm::vec3& p, float h) const {
  const glm::vec3 dx(h, 0, 0), dy(0, h, 0), dz(0, 0, h);
  const glm::vec3 g(value(p + dx) - value(p - dx), value(p + dy) - value(p - dy), value(p + dz) - value(p - dz));
  const float len = glm::length(g);
  return len > 0.0f ? g / len : glm::vec3(0, 1, 0);
}

void ImplicitBody::potentials(const glm::vec3& p, float falloff, std::vector<float>& out) const {
  out.resize(primitives_.size());
  for (size_t i = 0; i < primitives_.size(); ++i)
    out[i] = std::exp(-std::max(primitives_[i].distance(p), 0.0f) / falloff);
}

ScalarGrid ImplicitBody::sample(float cellSize, ThreadPool* pool) const {
  constexpr int kBlock = 8;
  // Summed potentials push the skin out by at most blend * ln(overlapping
  // primitives) beyond the shapes; 4 blends covers a dozen overlaps.
  Aabb box;
  float largestBlend = 0.0f;
  for (const ImplicitPrimitive& p : primitives_) {
    box.extend(p.extent.min);
    box.extend(p.extent.max);
    largestBlend = std::max(largestBlend, p.blend);
  }
  const glm::vec3 margin(4.0f * largestBlend + 2.0f * cellSize);
  if (hasGround_) box.min.y = std::max(box.min.y, groundHeight_);
  ScalarGrid grid;
  grid.cellSize = cellSize;
  grid.origin = box.min - margin;
  grid.dims = glm::ivec3(glm::ceil((box.max + margin - grid.origin) / cellSize)) + 1;
  grid.values.resize(size_t(grid.dims.x) * grid.dims.y * grid.dims.z);
  const glm::ivec3 blocks = (grid.dims + (kBlock - 1)) / kBlock;
  const size_t blockCount = size_t(blocks.x) * blocks.y * blocks.z;

  auto sampleBlocks = [&](size_t begin, size_t end) {
    std::vector<int> candidates;
    for (size_t b = begin; b < end; ++b) {
      const glm::ivec3 block(int(b % blocks.x), int((b / blocks.x) % blocks.y), int(b / (size_t(blocks.x) * blocks.y)));
      const glm::ivec3 lo = block * kBlock;
      const glm::ivec3 hi = glm::min(lo + kBlock, grid.dims) - 1;
      const glm::vec3 boxMin = grid.point(lo.x, lo.y, lo.z), boxMax = grid.point(hi.x, hi.y, hi.z);
      candidates.clear();
      for (size_t i = 0; i < primitives_.size(); ++i) {
        const Aabb& s = primitives_[i].support;
        if (glm::all(glm::lessThanEqual(s.min, boxMax)) && glm::all(glm::lessThanEqual(boxMin, s.max)))
          candidates.push_back(int(i));
      }
      for (int k = lo.z; k <= hi.z; ++k)
        for (int j = lo.y; j <= hi.y; ++j)
          for (int i = lo.x; i <= hi.x; ++i)
            grid.values[grid.index(i, j, k)] = valueFrom(grid.point(i, j, k), candidates.data(), candidates.size());
    }
  };
  if (pool)
    pool->parallelFor(0, blockCount, 4, sampleBlocks);
  else
    sampleBlocks(0, blockCount);
  return grid;
}

}  // namespace mq
