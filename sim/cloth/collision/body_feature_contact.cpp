#include "sim/cloth/collision/body_feature_contact.h"

#include <algorithm>
#include <cmath>

#include "sim/cloth/collision/proximity.h"
#include "sim/cloth/parallel.h"

namespace mq::cloth {

namespace {

// The gap kept between a body vertex and the cloth triangle over it, as a
// fraction of the collision thickness. Less than the whole thickness: cloth
// resting on a convex body part at the thickness has its triangles' middles a
// little closer (the chord), and pushing those out every step would only
// make the cloth float; a pierced triangle is pushed to this gap at once.
constexpr float kGapFraction = 0.5f;
// Cloth triangles nearly edge-on to the body surface (a fold standing on it)
// have no clear outside: skipped below this |cos| between the normals.
constexpr float kMinAlignment = 0.3f;
// A cloth point behind a body vertex and outside the body, whose nearest
// body surface faces away from the vertex's outside by more than this cos, is
// beyond a thin body part (a hand over a sleeve), not pierced.
constexpr float kBeyond = -0.5f;
constexpr int kPasses = 4;
constexpr size_t kBlocks = 64;

}  // namespace

BodyFeatureContact::BodyFeatureContact(const std::vector<uint32_t>& clothTriangles) : triangles_(clothTriangles) {}

void BodyFeatureContact::prepareBody(const BodyCollider& body) {
  const std::vector<uint32_t>& triangles = body.triangles();
  if (triangles.size() == bodyTriangleCount_ && ringStart_.size() == body.positions().size() + 1) return;
  const size_t n = body.positions().size();
  ringStart_.assign(n + 1, 0);
  for (uint32_t v : triangles) ++ringStart_[v + 1];
  for (size_t v = 0; v < n; ++v) ringStart_[v + 1] += ringStart_[v];
  ringTriangles_.resize(triangles.size());
  std::vector<uint32_t> fill(ringStart_.begin(), ringStart_.end() - 1);
  for (size_t e = 0; e < triangles.size(); ++e) ringTriangles_[fill[triangles[e]]++] = uint32_t(e / 3);
  bodyTriangleCount_ = triangles.size();
}

void BodyFeatureContact::updateTree(const ClothState& s) {
  const std::vector<Box> boxes = triangleBoxes(s.x, triangles_, 0.0f);
  if (callsSinceBuild_ >= kRebuildEvery || tree_.empty()) {
    tree_.build(boxes);
    callsSinceBuild_ = 0;
  } else {
    tree_.refit(boxes);
  }
  ++callsSinceBuild_;
}

std::vector<BodyFeatureContact::Contact> BodyFeatureContact::findContacts(const ClothState& s,
                                                                          const BodyCollider& body,
                                                                          float thickness) const {
  const std::vector<glm::vec3>& bodyX = body.positions();
  const std::vector<uint32_t>& bodyTriangles = body.triangles();
  const float gap = kGapFraction * thickness;
  // Area-weighted outward normal of body vertex v (unnormalised).
  auto outward = [&](uint32_t v) {
    glm::vec3 sum(0.0f);
    for (uint32_t k = ringStart_[v]; k < ringStart_[v + 1]; ++k) {
      const uint32_t* t = &bodyTriangles[3 * ringTriangles_[k]];
      sum += glm::cross(bodyX[t[1]] - bodyX[t[0]], bodyX[t[2]] - bodyX[t[0]]);
    }
    return sum;
  };
  const size_t count = bodyX.size(), blockSize = (count + kBlocks - 1) / kBlocks;
  std::vector<std::vector<Contact>> blocks(kBlocks);
  auto scan = [&](size_t block) {
    std::vector<Contact>& out = blocks[block];
    for (size_t v = block * blockSize; v < std::min(count, (block + 1) * blockSize); ++v) {
      const glm::vec3 p = bodyX[v];
      Box box;
      box.extend(p);
      box.min -= glm::vec3(kMaxDepth);
      box.max += glm::vec3(kMaxDepth);
      glm::vec3 bodyNormal(0.0f);
      bool normalKnown = false;
      const size_t first = out.size();
      tree_.query(box, [&](uint32_t t) {
        const uint32_t a = triangles_[3 * t], b = triangles_[3 * t + 1], c = triangles_[3 * t + 2];
        const glm::vec3 faceNormal = glm::cross(s.x[b] - s.x[a], s.x[c] - s.x[a]);
        const float area2 = glm::length(faceNormal);
        if (!(area2 > 0.0f)) return;
        const glm::vec3 n = faceNormal / area2;
        const float plane = glm::dot(s.x[a] - p, n);  // the triangle's plane seen from p, along n
        if (std::abs(plane) > kMaxDepth) return;
        if (!normalKnown) {
          bodyNormal = outward(uint32_t(v));
          const float l = glm::length(bodyNormal);
          bodyNormal = l > 0.0f ? bodyNormal / l : glm::vec3(0.0f);
          normalKnown = true;
        }
        const float alignment = glm::dot(n, bodyNormal);
        if (std::abs(alignment) < kMinAlignment) return;
        const float side = alignment > 0.0f ? 1.0f : -1.0f;
        const float height = side * plane;  // > 0: the triangle is in front of the body vertex
        if (height >= gap || height < -kMaxDepth) return;
        // Only a body vertex under the triangle (not beside it) is in contact.
        const glm::vec3 w = closestTriangleWeights(p, s.x[a], s.x[b], s.x[c]);
        const glm::vec3 q = w.x * s.x[a] + w.y * s.x[b] + w.z * s.x[c];
        const glm::vec3 offset = q - p;
        if (glm::length(offset - glm::dot(offset, n) * n) > thickness) return;
        // Behind the body vertex, the triangle's point is inside the body or
        // beside the tip the vertex is (a sharp feature); outside with the
        // body's surface between it and the vertex (the surface facing away
        // from the vertex's side), it is cloth beyond a thin body part.
        BodyContact contact;
        const bool near = body.nearestContact(q, contact, kMaxDepth + thickness);
        if (height < 0.0f && near && contact.signedDistance >= 0.0f && glm::dot(contact.normal, side * n) < kBeyond)
          return;
        out.push_back({uint32_t(v), t, w, side, near ? contact.velocity : glm::vec3(0.0f)});
      });
      // In order of the triangle (the tree's order depends on the boxes).
      std::sort(out.begin() + first, out.end(),
                [](const Contact& x, const Contact& y) { return x.triangle < y.triangle; });
    }
  };
  if (count < 2 * kParallelGrain)
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
bool BodyFeatureContact::apply(ClothState& s, const BodyCollider& body, const Contact& c, float thickness) const {
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
  const float gap = kGapFraction * thickness;
  if (height >= gap || denom <= 0.0f) return false;
  const float push = (gap - height) / denom;
  const float vn = glm::dot(velocity - c.surfaceVelocity, n);
  const float stop = vn < 0.0f ? -vn / denom : 0.0f;
  for (int k = 0; k < 3; ++k) {
    s.x[v[k]] += (push * w[k] * s.invMass[v[k]]) * n;
    s.v[v[k]] += (stop * w[k] * s.invMass[v[k]]) * n;
  }
  return true;
}

int BodyFeatureContact::resolve(ClothState& s, const BodyCollider& body, float thickness,
                                std::vector<uint8_t>& touched, uint8_t mark) {
  if (body.empty() || triangles_.empty()) return 0;
  prepareBody(body);
  updateTree(s);
  const std::vector<Contact> contacts = findContacts(s, body, thickness);
  for (int pass = 0; pass < kPasses; ++pass) {
    bool any = false;
    for (const Contact& c : contacts) {
      if (!apply(s, body, c, thickness)) continue;
      any = true;
      for (int k = 0; k < 3; ++k) {
        const uint32_t vertex = triangles_[3 * c.triangle + k];
        if (s.invMass[vertex] > 0.0f) touched[vertex] = std::max(touched[vertex], mark);
      }
    }
    if (!any) break;
  }
  return int(contacts.size());
}

}  // namespace mq::cloth
