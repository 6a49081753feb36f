// The body collider's inside/outside test near edges and vertices of a
// non-convex closed mesh: an L-shaped prism, whose notch has a reflex edge
// and saddle-like corners where a nearest triangle's own normal can point
// either way.
#include <gtest/gtest.h>

#include <random>

#include "sim/cloth/collision/body_collider.h"
#include "sim/cloth/collision/proximity.h"

namespace mq::cloth {
namespace {

constexpr float kUnit = 0.05f;  // m; the L is 2 x 2 units, 1 unit thick

// The L polygon in the xy plane, counter-clockwise, extruded along z from 0 to kUnit.
void lPrism(std::vector<float>& positions, std::vector<uint32_t>& triangles) {
  const float corners[6][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  for (float z : {0.0f, 1.0f})
    for (const auto& c : corners) positions.insert(positions.end(), {kUnit * c[0], kUnit * c[1], kUnit * z});
  // Caps: a fan from corner 0, which sees every other corner.
  for (uint32_t i = 1; i + 1 < 6; ++i) {
    triangles.insert(triangles.end(), {0, i + 1, i});          // bottom, facing -z
    triangles.insert(triangles.end(), {6, 6 + i, 6 + i + 1});  // top, facing +z
  }
  for (uint32_t i = 0; i < 6; ++i) {
    const uint32_t j = (i + 1) % 6;
    triangles.insert(triangles.end(), {i, j, 6 + j, i, 6 + j, 6 + i});
  }
}

bool insideL(const glm::vec3& p) {
  const glm::vec3 u = p / kUnit;
  if (u.z <= 0.0f || u.z >= 1.0f || u.x <= 0.0f || u.y <= 0.0f) return false;
  return (u.x < 2.0f && u.y < 1.0f) || (u.x < 1.0f && u.y < 2.0f);
}

TEST(BodyCollider, TellsInsideFromOutsideNearEdgesAndCornersOfANonConvexBody) {
  std::vector<float> positions;
  std::vector<uint32_t> triangles;
  lPrism(positions, triangles);
  BodyCollider body;
  body.setMesh(positions, triangles, 0.02f);
  // Points around the notch's corners and reflex edge, and the outer corners.
  std::mt19937 random(7);
  std::uniform_real_distribution<float> offset(-0.4f, 0.4f);
  const glm::vec3 spots[] = {{1, 1, 1}, {1, 1, 0}, {1, 1, 0.5f}, {2, 1, 1}, {1, 2, 1}, {0, 0, 1}, {2, 0, 0}};
  int checked = 0, wrong = 0;
  for (const glm::vec3& spot : spots)
    for (int k = 0; k < 4000; ++k) {
      const glm::vec3 p = kUnit * (spot + glm::vec3(offset(random), offset(random), offset(random)));
      BodyContact contact;
      if (!body.nearestContact(p, contact) || std::abs(contact.signedDistance) < 1e-5f) continue;
      ++checked;
      wrong += (contact.signedDistance < 0.0f) != insideL(p);
    }
  EXPECT_GT(checked, 20000);
  EXPECT_EQ(wrong, 0) << "of " << checked;
}

TEST(BodyCollider, PushesOutAlongTheShortestWayToTheSurface) {
  std::vector<float> positions;
  std::vector<uint32_t> triangles;
  lPrism(positions, triangles);
  BodyCollider body;
  body.setMesh(positions, triangles, 0.02f);
  // Just inside the reflex edge of the notch: out is diagonal, into the notch.
  const glm::vec3 p = kUnit * glm::vec3(0.95f, 0.95f, 0.5f);
  BodyContact contact;
  ASSERT_TRUE(body.nearestContact(p, contact));
  EXPECT_LT(contact.signedDistance, 0.0f);
  EXPECT_NEAR(contact.normal.x, std::sqrt(0.5f), 1e-3f);
  EXPECT_NEAR(contact.normal.y, std::sqrt(0.5f), 1e-3f);
  EXPECT_NEAR(contact.normal.z, 0.0f, 1e-3f);
}

// A closed, bumpy sphere (a UV sphere with a wavy radius), 1,600 triangles.
void bumpySphere(float phase, std::vector<float>& positions, std::vector<uint32_t>& triangles) {
  constexpr int kRings = 20, kSegments = 40;
  positions.clear();
  triangles.clear();
  auto at = [&](float theta, float phi) {
    const float r = 0.1f * (1.0f + 0.15f * std::sin(5.0f * phi + phase) * std::sin(3.0f * theta));
    positions.insert(positions.end(), {r * std::sin(theta) * std::cos(phi), r * std::cos(theta), r * std::sin(theta) * std::sin(phi)});
  };
  at(0.0f, 0.0f);  // north pole: vertex 0
  for (int i = 1; i < kRings; ++i)
    for (int j = 0; j < kSegments; ++j) at(float(M_PI) * i / kRings, 2.0f * float(M_PI) * j / kSegments);
  at(float(M_PI), 0.0f);  // south pole
  const uint32_t south = uint32_t(positions.size() / 3 - 1);
  auto ring = [](int i, int j) { return uint32_t(1 + (i - 1) * kSegments + (j % kSegments)); };
  for (int j = 0; j < kSegments; ++j) {
    triangles.insert(triangles.end(), {0, ring(1, j + 1), ring(1, j)});
    triangles.insert(triangles.end(), {south, ring(kRings - 1, j), ring(kRings - 1, j + 1)});
    for (int i = 1; i + 1 < kRings; ++i)
      triangles.insert(triangles.end(), {ring(i, j), ring(i, j + 1), ring(i + 1, j + 1), ring(i, j), ring(i + 1, j + 1), ring(i + 1, j)});
  }
}

// The bumpy sphere as a body (2 cm search radius) and, as `target`, the same
// sphere with its bumps turned (phase 0.7): a pose to move to.
struct BumpyBody {
  std::vector<float> rest, target;
  std::vector<uint32_t> triangles;
  BodyCollider body;
  BumpyBody() {
    bumpySphere(0.0f, rest, triangles);
    bumpySphere(0.7f, target, triangles);
    body.setMesh(rest, triangles, 0.02f);
  }
};

// The tree only prunes: the nearest contact is the nearest of all triangles,
// at rest and half way through a move (where the boxes have moved).
TEST(BodyCollider, NearestContactIsTheNearestOfAllTriangles) {
  BumpyBody bumpy;
  BodyCollider& body = bumpy.body;
  const std::vector<uint32_t>& triangles = bumpy.triangles;
  const std::vector<float>& target = bumpy.target;
  std::mt19937 random(11);
  std::uniform_real_distribution<float> where(-0.13f, 0.13f);
  int found = 0;
  for (float fraction : {0.0f, 0.5f}) {
    body.setTarget(target, 1.0f / 30.0f);
    body.moveTo(fraction);
    const std::vector<glm::vec3>& x = body.positions();
    for (int q = 0; q < 3000; ++q) {
      const glm::vec3 p(where(random), where(random), where(random));
      float expected = 1e30f;
      for (size_t t = 0; t < triangles.size() / 3; ++t) {
        const glm::vec3 &a = x[triangles[3 * t]], &b = x[triangles[3 * t + 1]], &c = x[triangles[3 * t + 2]];
        const glm::vec3 w = closestTriangleWeights(p, a, b, c);
        expected = std::min(expected, glm::length(p - (w.x * a + w.y * b + w.z * c)));
      }
      BodyContact contact;
      const bool hit = body.nearestContact(p, contact, 0.02f);
      ASSERT_EQ(hit, expected < 0.02f) << "at " << p.x << " " << p.y << " " << p.z;
      if (!hit) continue;
      ++found;
      EXPECT_NEAR(std::abs(contact.signedDistance), expected, 1e-6f);
      EXPECT_NEAR(glm::length(p - contact.point), expected, 1e-6f);
    }
  }
  EXPECT_GT(found, 1000);
}

bool sameContact(const BodyContact& a, const BodyContact& b) {
  return a.point == b.point && a.normal == b.normal && a.velocity == b.velocity &&
         a.signedDistance == b.signedDistance && a.triangle == b.triangle;
}

// A point's queries through its last one (BodyQuery) answer exactly as a
// fresh search, bit for bit: from the same point (reused), after small and
// large moves (the last triangle as the hint; far enough from the surface
// for the radius: no search at all), and after the body moved (the last
// query no longer holds).
TEST(BodyCollider, QueriesFromTheLastQueryAnswerAsAFreshSearch) {
  BumpyBody bumpy;
  BodyCollider& body = bumpy.body;
  const std::vector<uint32_t>& triangles = bumpy.triangles;
  const std::vector<float>& target = bumpy.target;
  body.setTarget(target, 1.0f / 30.0f);
  std::mt19937 random(5);
  std::uniform_real_distribution<float> where(-0.13f, 0.13f), step(-0.004f, 0.004f);
  std::vector<BodyQuery> last(500);
  std::vector<glm::vec3> points(last.size());
  for (glm::vec3& p : points) p = {where(random), where(random), where(random)};
  long long queries = 0, searched = 0, provenEmpty = 0, found = 0;
  for (float fraction : {0.0f, 0.5f, 1.0f}) {
    body.moveTo(fraction);
    for (int round = 0; round < 6; ++round)
      for (size_t i = 0; i < points.size(); ++i) {
        // Every third round from the same point; otherwise a few mm on, or a jump.
        if (round % 3 != 2) points[i] += round == 4 ? glm::vec3(where(random), 0, 0) : glm::vec3(step(random), step(random), step(random));
        // The wide ones prove the narrow ones' misses, and answer them from the same point.
        const float radius = round == 0 || round == 5 ? 0.05f : 0.02f;
        BodyContact fresh, kept;
        const bool hit = body.nearestContact(points[i], fresh, radius);
        ++queries;
        if (body.provesNoneWithin(last[i], points[i], radius)) {
          ++provenEmpty;
          ASSERT_FALSE(hit) << "proven empty, yet a contact at " << fresh.signedDistance;
          continue;
        }
        const uint32_t before = last[i].searches;
        ASSERT_EQ(body.nearestContact(points[i], kept, radius, last[i]), hit);
        searched += last[i].searches - before;
        if (!hit) continue;
        ++found;
        EXPECT_TRUE(sameContact(fresh, kept)) << "query " << queries;
        // Any triangle as the hint: the same answer.
        BodyContact hinted;
        ASSERT_TRUE(body.nearestContact(points[i], hinted, radius, int32_t(random() % (triangles.size() / 3))));
        EXPECT_TRUE(sameContact(fresh, hinted));
      }
  }
  EXPECT_GT(found, 1000);
  EXPECT_GT(provenEmpty, 500);                   // far points moved a little: no search
  EXPECT_LT(searched, queries - provenEmpty - 800);  // unmoved points: the answer again
}

// An answer kept from the same point takes the body's velocity of the new
// frame (setTarget() changes it without moving the body).
TEST(BodyCollider, AKeptAnswerTakesTheBodysNewVelocity) {
  std::vector<float> positions, target;
  std::vector<uint32_t> triangles;
  bumpySphere(0.0f, positions, triangles);
  BodyCollider body;
  body.setMesh(positions, triangles, 0.02f);
  const glm::vec3 p(0.0f, 0.11f, 0.0f);
  BodyQuery last;
  BodyContact contact;
  for (float lift : {0.01f, 0.03f}) {
    target = positions;
    for (size_t i = 1; i < target.size(); i += 3) target[i] += lift;
    body.setTarget(target, 0.1f);
    ASSERT_TRUE(body.nearestContact(p, contact, 0.02f, last));
    EXPECT_NEAR(contact.velocity.y, lift / 0.1f, 1e-5f);
  }
  EXPECT_EQ(last.searches, 1u);
}

// A segment without a hit is not tested again in the same move, but is in
// the next one (where the body moved across it).
TEST(BodyCollider, FirstHitAlongRetestsASegmentAfterTheBodyMoved) {
  std::vector<float> positions, target;
  std::vector<uint32_t> triangles;
  bumpySphere(0.0f, positions, triangles);
  target = positions;
  for (size_t i = 0; i < target.size(); i += 3) target[i] += 0.1f;  // the sphere moves 10 cm along +x
  BodyCollider body;
  body.setMesh(positions, triangles, 0.02f);
  // A still point 2 cm outside the sphere's +x side, in its way.
  const glm::vec3 p(0.14f, 0.0f, 0.0f);
  BodyQuery last;
  BodyContact contact;
  EXPECT_FALSE(body.firstHitAlong(p, p, contact, last));
  EXPECT_FALSE(body.firstHitAlong(p, p, contact, last));
  body.setTarget(target, 1.0f / 30.0f);
  body.moveTo(1.0f);
  EXPECT_TRUE(body.firstHitAlong(p, p, contact, last));
  BodyContact fresh;
  EXPECT_TRUE(body.firstHitAlong(p, p, fresh));
}

}  // namespace
}  // namespace mq::cloth
