#include "core/hair/body_proxy.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include <Eigen/Dense>

#include "core/character/posed_character.h"
#include "core/hair/scalp.h"
#include "core/hair/static_head.h"
#include "core/util/error.h"

namespace mq {

namespace {

constexpr float kPi = 3.14159265358979f;

// Point of the ellipsoid's own frame, divided by the (grown) radii: inside when |q| < 1.
glm::vec3 scaledLocal(const Ellipsoid& e, const glm::vec3& p, float margin) {
  return (glm::transpose(e.axes) * (p - e.center)) / (e.radii + glm::vec3(margin));
}

glm::vec3 closestOnSegment(const Capsule& c, const glm::vec3& p) {
  const glm::vec3 ab = c.b - c.a;
  const float len2 = glm::dot(ab, ab);
  const float t = len2 > 0.0f ? std::clamp(glm::dot(p - c.a, ab) / len2, 0.0f, 1.0f) : 0.0f;
  return c.a + t * ab;
}

glm::vec4 boundingSphere(const Ellipsoid& e) { return {e.center, std::max({e.radii.x, e.radii.y, e.radii.z})}; }
glm::vec4 boundingSphere(const Capsule& c) { return {0.5f * (c.a + c.b), 0.5f * glm::length(c.b - c.a) + c.radius}; }

bool insideEllipsoid(const Ellipsoid& e, const glm::vec3& p, float margin) {
  const glm::vec3 q = scaledLocal(e, p, margin);
  return glm::dot(q, q) < 1.0f;
}

bool mayReachEllipsoid(const Ellipsoid& e, const glm::vec3& p, float distance) {
  const float smallest = std::min({e.radii.x, e.radii.y, e.radii.z});
  const float limit = 1.0f + distance / std::max(smallest, 1e-6f);
  const glm::vec3 q = scaledLocal(e, p, 0.0f);
  return glm::dot(q, q) < limit * limit;
}

bool insideCapsule(const Capsule& c, const glm::vec3& p, float margin) {
  const glm::vec3 d = p - closestOnSegment(c, p);
  const float r = c.radius + margin;
  return glm::dot(d, d) < r * r;
}

float ellipsoidArea(const glm::vec3& r) {
  const float p = 1.6075f;  // Knud Thomsen's approximation, within 1.1%
  const float ab = std::pow(r.x * r.y, p), ac = std::pow(r.x * r.z, p), bc = std::pow(r.y * r.z, p);
  return 4.0f * kPi * std::pow((ab + ac + bc) / 3.0f, 1.0f / p);
}

float capsuleArea(const Capsule& c) {
  return 2.0f * kPi * c.radius * glm::length(c.b - c.a) + 4.0f * kPi * c.radius * c.radius;
}

glm::vec3 fibonacciDirection(int i, int n) {
  const float golden = kPi * (3.0f - std::sqrt(5.0f));
  const float y = 1.0f - 2.0f * (float(i) + 0.5f) / float(n);
  const float r = std::sqrt(std::max(0.0f, 1.0f - y * y));
  return {r * std::cos(golden * float(i)), y, r * std::sin(golden * float(i))};
}

// Orthonormal basis with `axis` as its third column.
glm::mat3 frameAround(const glm::vec3& axis) {
  const glm::vec3 w = glm::normalize(axis);
  const glm::vec3 helper = std::abs(w.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  const glm::vec3 u = glm::normalize(glm::cross(helper, w));
  return glm::mat3(u, glm::cross(w, u), w);
}

void addEllipsoidPanels(const Ellipsoid& e, int n, SurfacePanels& out) {
  const float volumeFactor = e.radii.x * e.radii.y * e.radii.z;
  for (int i = 0; i < n; ++i) {
    const glm::vec3 u = fibonacciDirection(i, n);
    const glm::vec3 gradient = u / e.radii;  // normal direction in the local frame
    out.centers.push_back(e.center + e.axes * (e.radii * u));
    out.normals.push_back(glm::normalize(e.axes * gradient));
    // Area element of the map u -> radii * u: det * |radii^-1 n| * dOmega.
    out.areas.push_back(4.0f * kPi / float(n) * volumeFactor * glm::length(gradient));
    out.depths.push_back(std::min(std::sqrt(out.areas.back()), 0.5f * std::min({e.radii.x, e.radii.y, e.radii.z})));
  }
}

void addCapsulePanels(const Capsule& c, float spacing, SurfacePanels& out) {
  const float length = glm::length(c.b - c.a);
  const glm::mat3 frame = frameAround(length > 0.0f ? c.b - c.a : glm::vec3(0, 1, 0));
  const int rings = std::max(1, int(std::round(length / spacing)));
  const int segments = std::max(6, int(std::round(2.0f * kPi * c.radius / spacing)));
  const float ringArea = 2.0f * kPi * c.radius * length / float(rings * segments);
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      const float angle = 2.0f * kPi * (float(s) + 0.5f * float(r & 1)) / float(segments);
      const glm::vec3 n = frame * glm::vec3(std::cos(angle), std::sin(angle), 0.0f);
      out.centers.push_back(glm::mix(c.a, c.b, (float(r) + 0.5f) / float(rings)) + c.radius * n);
      out.normals.push_back(n);
      out.areas.push_back(ringArea);
      out.depths.push_back(std::min(std::sqrt(ringArea), 0.5f * c.radius));
    }
  const int capPanels = std::max(8, int(std::round(4.0f * kPi * c.radius * c.radius / (spacing * spacing))));
  for (int i = 0; i < capPanels; ++i) {
    const glm::vec3 n = frame * fibonacciDirection(i, capPanels);
    const bool atB = glm::dot(n, frame[2]) > 0.0f;
    out.centers.push_back((atB ? c.b : c.a) + c.radius * n);
    out.normals.push_back(n);
    out.areas.push_back(4.0f * kPi * c.radius * c.radius / float(capPanels));
    out.depths.push_back(std::min(std::sqrt(out.areas.back()), 0.5f * c.radius));
  }
}

}  // namespace

void BodyProxy::updateBounds() {
  const size_t shapes = ellipsoids.size() + capsules.size();
  cellMask_.clear();
  maskPalette_.clear();
  gridShapeCount_ = 0;
  if (shapes == 0 || shapes > 64) return;
  glm::vec3 lo(1e30f), hi(-1e30f);
  auto extend = [&](const glm::vec4& sphere) {
    lo = glm::min(lo, glm::vec3(sphere) - sphere.w);
    hi = glm::max(hi, glm::vec3(sphere) + sphere.w);
  };
  for (const Ellipsoid& e : ellipsoids) extend(boundingSphere(e));
  for (const Capsule& c : capsules) extend(boundingSphere(c));
  lo -= glm::vec3(kMaxCachedMargin);
  hi += glm::vec3(kMaxCachedMargin);
  const glm::vec3 extent = hi - lo;
  cellSize_ = std::max({extent.x, extent.y, extent.z}) / 64.0f;
  gridDims_ = glm::max(glm::ivec3(glm::ceil(extent / cellSize_)), glm::ivec3(1));
  gridOrigin_ = lo;
  cellMask_.assign(size_t(gridDims_.x) * gridDims_.y * gridDims_.z, 0);
  std::unordered_map<uint64_t, uint16_t> paletteIndex;
  // A cell may meet a shape grown by the margin only when its centre lies
  // within margin + half the cell diagonal of the shape. For an ellipsoid,
  // points within h of it have |scaled local| < 1 + h / (smallest radius)
  // (growing the radii by h is not enough: the offset surface bulges out).
  const float reach = kMaxCachedMargin + 0.8661f * cellSize_;
  for (int z = 0; z < gridDims_.z; ++z)
    for (int y = 0; y < gridDims_.y; ++y)
      for (int x = 0; x < gridDims_.x; ++x) {
        const glm::vec3 c = gridOrigin_ + (glm::vec3(x, y, z) + 0.5f) * cellSize_;
        uint64_t mask = 0;
        for (size_t i = 0; i < ellipsoids.size(); ++i)
          if (mayReachEllipsoid(ellipsoids[i], c, reach)) mask |= uint64_t(1) << i;
        for (size_t i = 0; i < capsules.size(); ++i)
          if (insideCapsule(capsules[i], c, reach)) mask |= uint64_t(1) << (ellipsoids.size() + i);
        auto [it, added] = paletteIndex.emplace(mask, uint16_t(maskPalette_.size()));
        if (added) {
          if (maskPalette_.size() > 0xFFFF) return;  // too many distinct masks: no grid
          maskPalette_.push_back(mask);
        }
        cellMask_[(size_t(z) * gridDims_.y + y) * gridDims_.x + x] = it->second;
      }
  gridShapeCount_ = shapes;
}

uint64_t BodyProxy::candidates(const glm::vec3& p, float margin) const {
  const size_t shapes = ellipsoids.size() + capsules.size();
  const uint64_t all = shapes >= 64 ? ~uint64_t(0) : (uint64_t(1) << shapes) - 1;
  if (gridShapeCount_ != shapes || shapes == 0 || margin > kMaxCachedMargin) return all;
  const glm::vec3 q = (p - gridOrigin_) / cellSize_;
  if (q.x < 0.0f || q.y < 0.0f || q.z < 0.0f) return 0;
  const glm::ivec3 c(q);
  if (c.x >= gridDims_.x || c.y >= gridDims_.y || c.z >= gridDims_.z) return 0;
  return maskPalette_[cellMask_[(size_t(c.z) * gridDims_.y + c.y) * gridDims_.x + c.x]];
}

bool BodyProxy::contains(const glm::vec3& p, float margin) const {
  return insideShapes(p, margin) || insideSurface(p, margin);
}

// The field's pushOut stops within a hundredth of a millimetre of the margin.
bool BodyProxy::insideSurface(const glm::vec3& p, float margin) const {
  return surface && surface->distance(p) < margin - 1e-5f;
}

bool BodyProxy::insideShapes(const glm::vec3& p, float margin) const {
  const uint64_t mask = candidates(p, margin);
  for (size_t i = 0; i < ellipsoids.size(); ++i)
    if ((mask >> i & 1) && insideEllipsoid(ellipsoids[i], p, margin)) return true;
  for (size_t i = 0; i < capsules.size(); ++i)
    if ((mask >> (ellipsoids.size() + i) & 1) && insideCapsule(capsules[i], p, margin)) return true;
  return false;
}

bool BodyProxy::pushOut(glm::vec3& p, float margin) const {
  // Out of the first shape that holds p, then again: a push out of one shape
  // can land inside another, a few rounds settle it.
  bool moved = false;
  const glm::vec3 start = p;
  for (int round = 0; round < 8; ++round) {
    const uint64_t mask = candidates(p, margin);
    bool movedThisRound = false;
    for (size_t i = 0; i < ellipsoids.size() && !movedThisRound; ++i) {
      if (!(mask >> i & 1)) continue;
      const Ellipsoid& e = ellipsoids[i];
      glm::vec3 q = scaledLocal(e, p, margin);
      const float len2 = glm::dot(q, q);
      if (len2 >= 1.0f) continue;
      q = len2 > 1e-12f ? q / std::sqrt(len2) : glm::vec3(0, 1, 0);
      p = e.center + e.axes * (q * (e.radii + glm::vec3(margin)) * 1.0001f);
      movedThisRound = true;
    }
    for (size_t i = 0; i < capsules.size() && !movedThisRound; ++i) {
      if (!(mask >> (ellipsoids.size() + i) & 1)) continue;
      const Capsule& c = capsules[i];
      const glm::vec3 base = closestOnSegment(c, p);
      glm::vec3 d = p - base;
      const float r = c.radius + margin;
      const float len2 = glm::dot(d, d);
      if (len2 >= r * r) continue;
      d = len2 > 1e-12f ? d / std::sqrt(len2) : frameAround(c.b - c.a)[0];
      p = base + d * (r * 1.0001f);
      movedThisRound = true;
    }
    if (!movedThisRound && insideSurface(p, margin)) movedThisRound = surface->pushOut(p, margin);
    if (!movedThisRound) return moved;
    moved = true;
  }
  // Still inside: caught in a crease between shapes that push it back and
  // forth. March on along the way it was being pushed until it is free of
  // the shapes (the surface's own push goes as far as its field can lead).
  glm::vec3 away = p - start;
  away = glm::dot(away, away) > 1e-18f ? glm::normalize(away) : glm::vec3(0, 1, 0);
  for (float step = 0.001f; insideShapes(p, margin) && step < 4.0f; step *= 1.5f) p += away * step;
  return moved;
}

SurfacePanels BodyProxy::makePanels(int targetCount) const {
  SurfacePanels all;
  if (empty() || targetCount <= 0) return all;
  // The head gets half the panels (the hair lives there), the rest share the other half by area.
  float restArea = 0.0f;
  for (size_t i = 1; i < ellipsoids.size(); ++i) restArea += ellipsoidArea(ellipsoids[i].radii);
  for (const Capsule& c : capsules) restArea += capsuleArea(c);
  const bool hasHead = !ellipsoids.empty();
  const int headPanels = !hasHead ? 0 : restArea > 0.0f ? targetCount / 2 : targetCount;
  if (hasHead) addEllipsoidPanels(ellipsoids[0], std::max(12, headPanels), all);
  const float spacing = std::sqrt(restArea / float(std::max(1, targetCount - headPanels)));
  for (size_t i = 1; i < ellipsoids.size(); ++i)
    addEllipsoidPanels(ellipsoids[i],
                       std::max(12, int(std::round(ellipsoidArea(ellipsoids[i].radii) / (spacing * spacing)))), all);
  for (const Capsule& c : capsules) addCapsulePanels(c, spacing, all);

  // Keep the panels on the union's boundary.
  SurfacePanels boundary;
  for (size_t i = 0; i < all.size(); ++i) {
    if (insideShapes(all.centers[i], -0.1f * std::sqrt(all.areas[i]))) continue;
    boundary.centers.push_back(all.centers[i]);
    boundary.normals.push_back(all.normals[i]);
    boundary.areas.push_back(all.areas[i]);
    boundary.depths.push_back(all.depths[i]);
  }
  return boundary;
}

BodyProxy sphereProxy(const glm::vec3& center, float radius) {
  BodyProxy proxy;
  proxy.ellipsoids.push_back({center, glm::mat3(1.0f), glm::vec3(radius)});
  proxy.updateBounds();
  return proxy;
}

namespace {

// For every vertex of every mesh: world rest position and the bone that
// drives it most (-1 when none).
struct DrivenVertices {
  std::vector<glm::vec3> positions;
  std::vector<int> bones;
};

DrivenVertices drivenVertices(const Character& character, std::vector<glm::mat4>& worldFromBone) {
  PosedCharacter posed;
  posed.evaluate(character, -1, 0.0f, nullptr, nullptr);
  worldFromBone = posed.worldFromBone();
  DrivenVertices out;
  for (size_t m = 0; m < character.meshes.size(); ++m) {
    const Mesh& mesh = character.meshes[m];
    const std::vector<float>& world = posed.meshes()[m].positions;
    for (size_t v = 0; v < mesh.vertexCount(); ++v) {
      out.positions.emplace_back(world[3 * v], world[3 * v + 1], world[3 * v + 2]);
      out.bones.push_back(dominantBone(mesh, v));
    }
  }
  return out;
}

bool isDescendantOrSelf(const Skeleton& skeleton, int bone, int ancestor) {
  for (int b = bone; b >= 0; b = skeleton.bone(b).parent)
    if (b == ancestor) return true;
  return false;
}

glm::vec3 origin(const glm::mat4& m) { return glm::vec3(m[3]); }

glm::mat3 orthonormalRotation(const glm::mat4& m) {
  glm::vec3 x = glm::normalize(glm::vec3(m[0]));
  glm::vec3 y = glm::vec3(m[1]);
  y = glm::normalize(y - glm::dot(y, x) * x);
  return glm::mat3(x, y, glm::cross(x, y));
}

// Least-squares axis-aligned quadric A x^2 + B y^2 + C z^2 + D x + E y + F z = 1
// in `frame`; falls back to the bounding box when the fit is not an ellipsoid.
Ellipsoid fitEllipsoid(const std::vector<glm::vec3>& points, const glm::mat3& frame, const glm::vec3& pivot) {
  glm::vec3 lo(1e30f), hi(-1e30f);
  Eigen::MatrixXd rows(points.size(), 6);
  Eigen::VectorXd ones = Eigen::VectorXd::Ones(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    const glm::vec3 q = glm::transpose(frame) * (points[i] - pivot);
    lo = glm::min(lo, q);
    hi = glm::max(hi, q);
    rows.row(i) << q.x * q.x, q.y * q.y, q.z * q.z, q.x, q.y, q.z;
  }
  Ellipsoid box{pivot + frame * (0.5f * (lo + hi)), frame, glm::max(0.5f * (hi - lo), glm::vec3(1e-3f))};
  const Eigen::VectorXd k = rows.colPivHouseholderQr().solve(ones);
  if (!(k[0] > 0 && k[1] > 0 && k[2] > 0)) return box;
  const glm::dvec3 c(-k[3] / (2 * k[0]), -k[4] / (2 * k[1]), -k[5] / (2 * k[2]));
  const double g = 1.0 + k[0] * c.x * c.x + k[1] * c.y * c.y + k[2] * c.z * c.z;
  if (!(g > 0)) return box;
  const glm::vec3 radii(std::sqrt(g / k[0]), std::sqrt(g / k[1]), std::sqrt(g / k[2]));
  const glm::vec3 extent = hi - lo;
  if (glm::any(glm::greaterThan(radii, extent))) return box;  // a wild fit to a small patch
  return {pivot + frame * glm::vec3(c), frame, radii};
}

// Capsule from bone `b` to `tipBone`, its radius the median distance of the
// vertices `b` drives; none when it drives fewer than 8.
bool boneCapsule(const DrivenVertices& verts, int b, const glm::vec3& start, const glm::vec3& end, Capsule& out) {
  Capsule c{start, end, 0.0f};
  std::vector<float> distances;
  for (size_t v = 0; v < verts.positions.size(); ++v)
    if (verts.bones[v] == b)
      distances.push_back(glm::length(verts.positions[v] - closestOnSegment(c, verts.positions[v])));
  if (distances.size() < 8) return false;
  std::nth_element(distances.begin(), distances.begin() + distances.size() / 2, distances.end());
  c.radius = 0.95f * distances[distances.size() / 2];
  if (c.radius <= 1e-3f) return false;
  out = c;
  return true;
}

void addBodyCapsules(const Character& character, int head, const DrivenVertices& verts,
                     const std::vector<glm::mat4>& worldFromBone, BodyProxy& proxy) {
  const Skeleton& skeleton = character.skeleton;
  auto addFromTo = [&](int bone, int tip) {
    Capsule c;
    if (boneCapsule(verts, bone, origin(worldFromBone[bone]), origin(worldFromBone[tip]), c))
      proxy.capsules.push_back(c);
  };
  const int neck = skeleton.bone(head).parent;
  if (neck < 0) return;
  addFromTo(neck, head);
  const int chest = skeleton.bone(neck).parent;
  if (chest < 0) return;
  addFromTo(chest, neck);
  // Shoulders: the chest's other children (clavicles) and their chains down to the elbows.
  for (int side : skeleton.children(chest)) {
    if (side == neck) continue;
    int bone = side;
    for (int depth = 0; depth < 2; ++depth) {
      const std::vector<int> next = skeleton.children(bone);
      if (next.empty()) break;
      addFromTo(bone, next[0]);
      bone = next[0];
    }
  }
  const int spine = skeleton.bone(chest).parent;
  if (spine >= 0) addFromTo(spine, chest);
}

// The head ellipsoid shrunk so that the roots sit on or outside it (at most
// by 15%), as the proxy's first shape.
BodyProxy finishHeadProxy(Ellipsoid e, const std::vector<glm::vec3>& scalpPoints) {
  float smallest = 1.0f;
  for (const glm::vec3& p : scalpPoints) smallest = std::min(smallest, glm::length(scaledLocal(e, p, 0.0f)));
  e.radii *= std::max(smallest * 0.995f, 0.85f);
  BodyProxy proxy;
  proxy.ellipsoids.push_back(e);
  return proxy;
}

// The distance field of every mesh of a static character around its head:
// the head grown sideways by a quarter of its height and down by a half (the
// shoulders of a body), in cells of an eightieth of the head's height.
std::shared_ptr<const MeshDistanceField> staticSurfaceField(const Character& character, const PosedCharacter& rest,
                                                            const std::vector<glm::vec3>& headPoints) {
  Aabb head;
  for (const glm::vec3& p : headPoints) head.extend(p);
  const float height = std::max(head.max.y - head.min.y, 0.01f);
  Aabb region = head;
  region.min -= glm::vec3(0.25f, 0.5f, 0.25f) * height;
  region.max += glm::vec3(0.25f, 0.1f, 0.25f) * height;
  const float cell = height / 80.0f;
  return std::make_shared<const MeshDistanceField>(concatenatedPositions(rest.meshes()),
                                                   concatenatedTriangles(character), region, cell, 4.0f * cell);
}

// A static mesh's head: an ellipsoid fitted in the world's axes to the
// vertices at its top. No capsules: there are no bones to find the neck and
// shoulders by.
BodyProxy fitStaticHeadProxy(const Character& character, const std::vector<glm::vec3>& scalpPoints) {
  PosedCharacter rest;
  rest.evaluate(character, -1, 0.0f, nullptr, nullptr);
  const std::vector<std::vector<uint8_t>> head = staticHeadVertices(character);
  std::vector<glm::vec3> headPoints;
  glm::vec3 centre(0.0f);
  for (size_t m = 0; m < head.size(); ++m)
    for (size_t v = 0; v < head[m].size(); ++v)
      if (head[m][v]) {
        const std::vector<float>& p = rest.meshes()[m].positions;
        headPoints.emplace_back(p[3 * v], p[3 * v + 1], p[3 * v + 2]);
        centre += headPoints.back();
      }
  if (headPoints.size() < 10) throw Error("the mesh of '" + character.name + "' has too few vertices for a head");
  centre /= float(headPoints.size());
  BodyProxy proxy = finishHeadProxy(fitEllipsoid(headPoints, glm::mat3(1.0f), centre), scalpPoints);
  proxy.surface = staticSurfaceField(character, rest, headPoints);
  proxy.updateBounds();
  return proxy;
}

}  // namespace

BodyProxy fitBodyProxy(const Character& character, const std::string& headBone,
                       const std::vector<glm::vec3>& scalpPoints) {
  if (character.skeleton.boneCount() == 0) return fitStaticHeadProxy(character, scalpPoints);
  const int head = character.skeleton.findBone(headBone);
  if (head < 0) throw Error("character '" + character.name + "' has no bone named '" + headBone + "'");
  std::vector<glm::mat4> worldFromBone;
  const DrivenVertices verts = drivenVertices(character, worldFromBone);
  std::vector<glm::vec3> headPoints;
  for (size_t v = 0; v < verts.positions.size(); ++v)
    if (verts.bones[v] >= 0 && isDescendantOrSelf(character.skeleton, verts.bones[v], head))
      headPoints.push_back(verts.positions[v]);
  if (headPoints.size() < 10)
    throw Error("bone '" + headBone + "' of character '" + character.name + "' drives too few vertices for a head");

  BodyProxy proxy = finishHeadProxy(
      fitEllipsoid(headPoints, orthonormalRotation(worldFromBone[head]), origin(worldFromBone[head])), scalpPoints);
  addBodyCapsules(character, head, verts, worldFromBone, proxy);
  proxy.updateBounds();
  return proxy;
}

}  // namespace mq
