#include <gtest/gtest.h>

#include <cmath>

#include "core/character/posed_character.h"
#include "core/skin_test_util.h"
#include "core/skinning/ellipse.h"
#include "core/skinning/section_cones.h"
#include "core/skinning/skin_metrics.h"
#include "core/util/thread_pool.h"

namespace mq {
namespace {

std::vector<glm::dvec2> rectangle(double w, double h, int perSide) {
  std::vector<glm::dvec2> out;
  const glm::dvec2 corners[4] = {{-w / 2, -h / 2}, {w / 2, -h / 2}, {w / 2, h / 2}, {-w / 2, h / 2}};
  for (int c = 0; c < 4; ++c)
    for (int i = 0; i < perSide; ++i)
      out.push_back(corners[c] + (double(i) / perSide) * (corners[(c + 1) % 4] - corners[c]));
  return out;
}

TEST(Ellipse, MomentEllipseOfARectangleHasItsAreaAndProportions) {
  const Ellipse2 e = momentEllipse(rectangle(2.0, 1.0, 1));
  ASSERT_TRUE(e.valid());
  EXPECT_NEAR(M_PI * e.a * e.b, 2.0, 1e-9);
  EXPECT_NEAR(e.a / e.b, 2.0, 1e-9);
  EXPECT_NEAR(std::abs(e.major.x), 1.0, 1e-9);
  EXPECT_NEAR(glm::length(e.center), 0.0, 1e-12);
}

TEST(Ellipse, EnclosingEllipseOfARectangleThroughItsCorners) {
  // The least-area ellipse around a w x h rectangle has semi-axes w/sqrt2, h/sqrt2.
  std::vector<glm::dvec2> points = rectangle(2.0, 1.0, 8);
  for (glm::dvec2& p : points) p += glm::dvec2(3.0, -1.0);
  const Ellipse2 e = enclosingEllipse(points);
  ASSERT_TRUE(e.valid());
  EXPECT_NEAR(e.a, 2.0 / std::sqrt(2.0), 1e-6);
  EXPECT_NEAR(e.b, 1.0 / std::sqrt(2.0), 1e-6);
  EXPECT_NEAR(e.center.x, 3.0, 1e-6);
  EXPECT_NEAR(e.center.y, -1.0, 1e-6);
  for (const glm::dvec2& p : points) {
    const glm::dvec2 d = p - e.center;
    EXPECT_LE(glm::length(d), e.radius(glm::normalize(d)) * (1 + 1e-9));
  }
}

TEST(Ellipse, ConicWithEitherSignGivesTheSameEllipse) {
  // (x-1)^2/4 + y^2 = 1  ->  0.25 x^2 + y^2 - 0.5 x - 0.75 = 0
  for (double sign : {1.0, -1.0}) {
    const Ellipse2 e = ellipseFromConic(sign * 0.25, sign * 1.0, 0.0, sign * -0.5, 0.0, sign * -0.75);
    ASSERT_TRUE(e.valid());
    EXPECT_NEAR(e.a, 2.0, 1e-12);
    EXPECT_NEAR(e.b, 1.0, 1e-12);
    EXPECT_NEAR(e.center.x, 1.0, 1e-12);
  }
  EXPECT_FALSE(ellipseFromConic(1.0, -1.0, 0.0, 0.0, 0.0, -1.0).valid());  // a hyperbola
}

TEST(SectionCones, TubeConesFitTheTube) {
  const Character c = tubeCharacter(41, 48, false);
  const auto cones = bindSectionCones(c.meshes[0], c.skeleton);
  ASSERT_EQ(cones->cones.size(), 2u);
  for (const SectionCone& cone : cones->cones) {
    ASSERT_TRUE(cone.valid);
    EXPECT_NEAR(cone.length, 1.0, 1e-6);
    for (int b = 0; b < 2; ++b) {
      // A 48-gon of radius 0.2: its area-equivalent circle is a little smaller.
      EXPECT_NEAR(cone.minimum[b].a, 0.2, 0.002);
      EXPECT_NEAR(cone.minimum[b].b, 0.2, 0.002);
      EXPECT_NEAR(cone.enclosing[b].a, 0.2, 1e-5);
    }
  }
  // A vertex on the tube sits on its cone: rho near 1.
  const SectionCone::Point at = cones->cones[0].locate({0.2, 0.5, 0.0});
  EXPECT_NEAR(at.s, 0.5, 1e-9);
  EXPECT_NEAR(at.rho, 1.0, 0.01);
  EXPECT_NEAR(at.rhoEnclosing, 1.0, 1e-4);
}

Character coneTube() {
  Character c = tubeCharacter(41, 48, false);
  c.skinning = SkinningMethod::Cones;
  return c;
}

std::vector<float> pose(const Character& c, float degrees, const glm::vec3& axis, ThreadPool* pool = nullptr) {
  PoseEdits edits;
  edits.rotations[1] = glm::angleAxis(glm::radians(degrees), axis);
  PosedCharacter posed;
  posed.evaluate(c, -1, 0.0f, &edits, pool);
  return posed.meshes()[0].positions;
}

TEST(SectionCones, RestPoseReproducesTheRestMesh) {
  const Character c = coneTube();
  const std::vector<float> p = pose(c, 0.0f, {0, 0, 1});
  for (size_t i = 0; i < p.size(); ++i) EXPECT_NEAR(p[i], c.meshes[0].positions[i], 1e-6f);
}

TEST(SectionCones, BendKeepsTheSectionAndTheVolume) {
  const Character cones = coneTube();
  const auto& rest = cones.meshes[0].positions;
  const auto& tris = cones.meshes[0].triangles;
  for (float degrees : {90.0f, 120.0f}) {
    const std::vector<float> corrected = pose(cones, degrees, {0, 0, 1});
    const OuterSection s = outerSection(rest, corrected, tris, tubeBend(degrees));
    EXPECT_GT(s.thickness, 0.95) << degrees;
    // The brief's band for the local volume (the fold pushed out of the
    // parent's cone adds back what interpenetration took).
    const double volume = localVolumeRatio(rest, corrected, tris, {0, 1, 0}, {0, 1, 0}, 0.3);
    EXPECT_GT(volume, 0.95) << degrees;
    EXPECT_LT(volume, 1.05) << degrees;
  }
}

TEST(SectionCones, SharpBendMakesACreaseInsteadOfCrossing) {
  // Bent at 130 degrees the tube's inner sides meet: DQS lets them cross,
  // the crease keeps each side of the joint plane (the tube's creases reach
  // 0.6 from the joint: enough for every crossing at this angle).
  Character cones = coneTube();
  Character dqs = cones;
  dqs.skinning = SkinningMethod::Dqs;
  const auto& tris = cones.meshes[0].triangles;
  const size_t crossingDqs = intersectingPairs(pose(dqs, 130.0f, {0, 0, 1}), tris);
  const std::vector<float> p = pose(cones, 130.0f, {0, 0, 1});
  EXPECT_GT(crossingDqs, 0u);
  EXPECT_EQ(intersectingPairs(p, tris), 0u);
  // Every vertex is on its rest side of the posed joint plane: through the
  // joint, normal to the axis turned by half the bend.
  const double half = glm::radians(65.0);
  const glm::dvec3 normal(-std::sin(half), std::cos(half), 0.0);
  for (size_t v = 0; v < cones.meshes[0].vertexCount(); ++v) {
    const double restHeight = cones.meshes[0].positions[3 * v + 1] - 1.0;
    const double height = glm::dot(glm::dvec3(p[3 * v], p[3 * v + 1], p[3 * v + 2]) - glm::dvec3(0, 1, 0), normal);
    if (std::abs(restHeight) > 1e-6 &&
        glm::length(glm::dvec3(cones.meshes[0].position(v)) - glm::dvec3(0, 1, 0)) < 0.6) {
      EXPECT_GT(restHeight * height, -1e-9) << "vertex " << v;
    }
  }
}

TEST(SectionCones, ThreadedEqualsSingleThreaded) {
  Character c = tubeCharacter(201, 64, false);  // enough vertices for the pool to split
  c.skinning = SkinningMethod::Cones;
  PoseEdits edits;
  edits.rotations[1] = glm::angleAxis(glm::radians(130.0f), glm::vec3(0, 0, 1));
  expectThreadedEqualsSingleThreaded(c, edits);
}

}  // namespace
}  // namespace mq
