// The body collider's inside/outside test near edges and vertices of a
// non-convex closed mesh: an L-shaped prism, whose notch has a reflex edge
// and saddle-like corners where a nearest triangle's own normal can point
// either way.
#include <gtest/gtest.h>

#include <random>

#include "core/character/default_mannequin.h"
#include "core/character/posed_character.h"
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
    positions.insert(positions.end(),
                     {r * std::sin(theta) * std::cos(phi), r * std::cos(theta), r * std::sin(theta) * std::sin(phi)});
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
      triangles.insert(triangles.end(), {ring(i, j), ring(i, j + 1), ring(i + 1, j + 1), ring(i, j), ring(i + 1, j + 1),
                                         ring(i + 1, j)});
  }
}

// The distance from p to triangle t of a mesh, and to the nearest of all its
// triangles (brute force).
float distanceToTriangle(const glm::vec3& p, const std::vector<glm::vec3>& x, const std::vector<uint32_t>& triangles,
                         size_t t) {
  const glm::vec3 &a = x[triangles[3 * t]], &b = x[triangles[3 * t + 1]], &c = x[triangles[3 * t + 2]];
  const glm::vec3 w = closestTriangleWeights(p, a, b, c);
  return glm::length(p - (w.x * a + w.y * b + w.z * c));
}
float distanceToMesh(const glm::vec3& p, const std::vector<glm::vec3>& x, const std::vector<uint32_t>& triangles) {
  float nearest = 1e30f;
  for (size_t t = 0; t < triangles.size() / 3; ++t) nearest = std::min(nearest, distanceToTriangle(p, x, triangles, t));
  return nearest;
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
      const float expected = distanceToMesh(p, x, triangles);
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

// The nearest triangle by brute force, as BodyCollider promises it: the
// least squared distance of closestTriangleWeights()'s point (lowest index
// among equals, degenerate triangles never), closer than `radius`; -1: none.
int32_t bruteForceNearest(const BodyCollider& body, const glm::vec3& p, float radius) {
  const std::vector<glm::vec3>& x = body.positions();
  const std::vector<uint32_t>& triangles = body.triangles();
  int32_t nearest = -1;
  float best2 = radius * radius;
  for (size_t t = 0; t < triangles.size() / 3; ++t) {
    const glm::vec3 &a = x[triangles[3 * t]], &b = x[triangles[3 * t + 1]], &c = x[triangles[3 * t + 2]];
    const glm::vec3 n = glm::cross(b - a, c - a);
    if (!(glm::dot(n, n) > 0.0f)) continue;
    const glm::vec3 w = closestTriangleWeights(p, a, b, c);
    const glm::vec3 offset = p - (w.x * a + w.y * b + w.z * c);
    const float d2 = glm::dot(offset, offset);
    if (d2 < best2) best2 = d2, nearest = int32_t(t);
  }
  return nearest;
}

// Points where a search is hardest to get exactly right: on the body's
// vertices (equally near to all triangles around), on its edges, a hair in
// front of and behind its triangles, and up to `spread` away from them.
std::vector<glm::vec3> probePoints(const BodyCollider& body, uint32_t seed, size_t count, float spread) {
  const std::vector<glm::vec3>& x = body.positions();
  const std::vector<uint32_t>& triangles = body.triangles();
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<glm::vec3> points;
  for (size_t k = 0; k < count; ++k) {
    const size_t t = random() % (triangles.size() / 3);
    const glm::vec3 &a = x[triangles[3 * t]], &b = x[triangles[3 * t + 1]], &c = x[triangles[3 * t + 2]];
    const glm::vec3 normal = glm::cross(b - a, c - a);
    const glm::vec3 n = glm::length(normal) > 0.0f ? glm::normalize(normal) : glm::vec3(0.0f, 0.0f, 1.0f);
    const float u = unit(random), v = unit(random) * (1.0f - u);
    switch (k % 5) {
      case 0:
        points.push_back(a);
        break;
      case 1:
        points.push_back(a + u * (b - a));
        break;
      case 2:
        points.push_back(a + u * (b - a) + v * (c - a) + (unit(random) - 0.5f) * 2e-6f * n);
        break;
      default:
        points.push_back(a + u * (b - a) + v * (c - a) + (unit(random) - 0.2f) * spread * n);
    }
  }
  return points;
}

void expectBruteForceNearest(const BodyCollider& body, const std::vector<glm::vec3>& points, float radius, int& found) {
  const size_t triangleCount = body.triangles().size() / 3;
  for (size_t i = 0; i < points.size(); ++i) {
    const glm::vec3& p = points[i];
    const int32_t expected = bruteForceNearest(body, p, radius);
    BodyContact contact, hinted;
    ASSERT_EQ(body.nearestContact(p, contact, radius), expected >= 0) << "point " << i;
    if (expected < 0) continue;
    ++found;
    ASSERT_EQ(contact.triangle, expected) << "point " << i;
    ASSERT_TRUE(body.nearestContact(p, hinted, radius, int32_t((7919 * i) % triangleCount)));
    EXPECT_TRUE(sameContact(contact, hinted)) << "point " << i;
  }
}

// The search's shortcuts (a lower bound for four triangles at once, the
// hint) only skip triangles: its answer is the brute-force nearest one
// exactly, on the moving bumpy sphere and on the walking mannequin.
TEST(BodyCollider, NearestTriangleIsTheBruteForceNearestExactly) {
  BumpyBody bumpy;
  BodyCollider& body = bumpy.body;
  body.setTarget(bumpy.target, 1.0f / 30.0f);
  int found = 0;
  for (float fraction : {0.0f, 0.5f}) {
    body.moveTo(fraction);
    body.moveTo(fraction);  // a move that does not move it keeps the trees as they are
    for (float radius : {0.005f, 0.02f, 0.08f})
      expectBruteForceNearest(body, probePoints(body, 3, 1500, 0.03f), radius, found);
  }
  EXPECT_GT(found, 3000);
}

// The default mannequin's body `t` s into its walk, its target one 1/30 s frame later.
BodyCollider walkingBodyFrameFrom(float t) {
  const Character mannequin = makeDefaultMannequin();
  const int walk = mannequin.findClip("walk");
  PosedCharacter posed;
  posed.evaluate(mannequin, walk, t, nullptr, nullptr);
  BodyCollider body;
  body.setMesh(concatenatedPositions(posed.meshes()), concatenatedTriangles(mannequin), 0.02f);
  posed.evaluate(mannequin, walk, t + 1.0f / 30.0f, nullptr, nullptr);
  body.setTarget(concatenatedPositions(posed.meshes()), 1.0f / 30.0f);
  return body;
}

TEST(BodyCollider, NearestTriangleOnTheWalkingMannequinIsTheBruteForceNearest) {
  BodyCollider body = walkingBodyFrameFrom(0.3f);
  body.moveTo(1.0f);
  int found = 0;
  expectBruteForceNearest(body, probePoints(body, 17, 300, 0.03f), 0.02f, found);
  expectBruteForceNearest(body, probePoints(body, 19, 100, 0.08f), 0.08f, found);
  EXPECT_GT(found, 300);
}

// Slivers and degenerate triangles (the skinned body's can be squeezed
// flat): a point's nearest triangle is still the brute-force one.
TEST(BodyCollider, NearestTriangleAmongSliversIsTheBruteForceNearest) {
  std::mt19937 random(23);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  std::vector<float> positions;
  std::vector<uint32_t> triangles;
  for (uint32_t k = 0; k < 60; ++k) {
    const glm::vec3 a(0.05f * unit(random), 0.05f * unit(random), 0.05f * unit(random));
    const glm::vec3 along = 0.01f * glm::vec3(unit(random), unit(random), unit(random));
    const glm::vec3 aside = float(std::pow(10.0f, -1.0f - 5.0f * (unit(random) + 1.0f))) *
                            glm::vec3(unit(random), unit(random), unit(random));
    // A sliver: its third corner near the line of the first two (on it, or at a corner, for every tenth).
    const glm::vec3 b = a + along, c = k % 10 == 0 ? a : a + (0.5f + 0.5f * unit(random)) * along + aside;
    for (const glm::vec3& v : {a, b, c}) positions.insert(positions.end(), {v.x, v.y, v.z});
    triangles.insert(triangles.end(), {3 * k, 3 * k + 1, 3 * k + 2});
  }
  BodyCollider body;
  body.setMesh(positions, triangles, 0.02f);
  int found = 0;
  expectBruteForceNearest(body, probePoints(body, 29, 3000, 0.01f), 0.02f, found);
  EXPECT_GT(found, 2000);
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
        if (round % 3 != 2)
          points[i] +=
              round == 4 ? glm::vec3(where(random), 0, 0) : glm::vec3(step(random), step(random), step(random));
        // The wide ones prove the narrow ones' misses, and answer them from the same point.
        const float radius = round == 0 || round == 5 ? 0.05f : 0.02f;
        BodyContact fresh, kept;
        const bool hit = body.nearestContact(points[i], fresh, radius);
        ++queries;
        // The same through the last query without updating it.
        BodyContact since;
        ASSERT_EQ(body.nearestContactSince(points[i], since, radius, last[i]), hit);
        if (hit) {
          EXPECT_TRUE(sameContact(fresh, since)) << "query " << queries;
        }
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
  EXPECT_GT(provenEmpty, 500);                       // far points moved a little: no search
  EXPECT_GT(provenEmpty, 3500);                      // with the clearance of a miss (3151 with its radius alone)
  EXPECT_GT(queries - provenEmpty - searched, 700);  // unmoved points: the answer again
}

// A miss keeps how far the surface is at least (the boxes and triangles the
// search passed over): never farther than the nearest triangle (brute force),
// and for a point well beyond the radius enough to prove the next miss a few
// mm on without a search.
TEST(BodyCollider, AMissesClearanceIsALowerBoundOfTheDistance) {
  BumpyBody bumpy;
  BodyCollider& body = bumpy.body;
  body.setTarget(bumpy.target, 1.0f / 30.0f);
  body.moveTo(0.5f);
  const std::vector<glm::vec3>& x = body.positions();
  const std::vector<uint32_t>& triangles = bumpy.triangles;
  auto distanceToBody = [&](const glm::vec3& p) { return distanceToMesh(p, x, triangles); };
  std::mt19937 random(17);
  std::uniform_real_distribution<float> where(-0.2f, 0.2f), step(-0.003f, 0.003f);
  const float radius = 0.02f;
  int misses = 0, far = 0, proven = 0, farProven = 0;
  for (int q = 0; q < 2000; ++q) {
    const glm::vec3 p(where(random), where(random), where(random));
    BodyQuery last;
    BodyContact contact;
    if (body.nearestContact(p, contact, radius, last)) continue;
    ++misses;
    const float distance = distanceToBody(p);
    ASSERT_GE(last.clearance, radius);
    ASSERT_LE(last.clearance, distance + 1e-6f) << "query " << q;
    const glm::vec3 moved = p + glm::vec3(step(random), step(random), step(random));
    if (body.provesNoneWithin(last, moved, radius)) {
      ++proven;
      ASSERT_GE(distanceToBody(moved), radius);
      ASSERT_FALSE(body.nearestContact(moved, contact, radius));
    }
    if (distance > radius + 0.02f) {
      ++far;
      farProven += body.provesNoneWithin(last, moved, radius);
    }
  }
  EXPECT_GT(misses, 1000);
  EXPECT_GT(far, 500);
  EXPECT_GT(10 * farProven, 9 * far);  // 1534 of 1615 (none with the radius alone)
  EXPECT_GE(proven, farProven);
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
