// The styling flow: panel method around a sphere, primitives, streamlines.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "core/hair/body_proxy.h"
#include "core/hair/flow_field.h"
#include "core/hair/strand_tracer.h"

namespace mq {
namespace {

constexpr float kRadius = 0.1f;

FlowField sphereFlow(const BodyProxy& proxy, const FlowPrimitives& primitives, int panels = 400) {
  FlowField field;
  field.setObstacle(proxy.makePanels(panels), {});
  field.setPrimitives(primitives, glm::vec3(0.0f), 0.0f);
  return field;
}

FlowPrimitives downStream(glm::vec3 direction = {0, -1, 0}) {
  FlowPrimitives p;
  p.streams.push_back({direction, 1.0f});
  return p;
}

TEST(HairFlow, BoundaryConditionHoldsAtEveryPanel) {
  const BodyProxy proxy = sphereProxy(glm::vec3(0.0f), kRadius);
  FlowPrimitives primitives = downStream({0.3f, -1.0f, 0.2f});
  primitives.sources.push_back({glm::vec3(0.0f, 0.15f, 0.05f), 0.5f, 0.05f});
  primitives.vortices.push_back({glm::vec3(0.05f, 0.0f, 0.0f), glm::vec3(0, 0, 1), 0.4f, 0.05f});
  FlowField field;
  const SurfacePanels panels = proxy.makePanels(300);
  std::vector<uint8_t> scalp(panels.size(), 0);
  for (size_t i = 0; i < panels.size(); ++i) scalp[i] = panels.normals[i].y > 0.3f;
  field.setObstacle(panels, scalp);
  field.setPrimitives(primitives, glm::vec3(0.0f), 0.7f);
  ASSERT_GT(panels.size(), 250u);
  float worst = 0.0f;
  for (int i = 0; i < int(panels.size()); ++i) {
    EXPECT_FLOAT_EQ(field.boundaryTarget(i), scalp[i] ? 0.7f : 0.0f);
    worst = std::max(worst, std::abs(field.panelNormalVelocity(i) - field.boundaryTarget(i)));
  }
  EXPECT_LT(worst, 1e-3f);
  // Without the panels the primitives alone would violate it badly.
  float unsolved = 0.0f;
  for (int i = 0; i < int(panels.size()); ++i)
    unsolved = std::max(unsolved, std::abs(glm::dot(field.primitiveVelocity(panels.centers[i]), panels.normals[i]) -
                                           field.boundaryTarget(i)));
  EXPECT_GT(unsolved, 0.5f);
}

TEST(HairFlow, NoFlowThroughTheSurfaceBetweenPanels) {
  // Desingularised sources: the condition also holds (approximately) away
  // from the collocation points, just above the surface.
  const BodyProxy proxy = sphereProxy(glm::vec3(0.0f), kRadius);
  const FlowField field = sphereFlow(proxy, downStream({0.2f, -1.0f, 0.1f}), 300);
  float worst = 0.0f;
  for (int i = 0; i < 2000; ++i) {
    const float y = 1.0f - 2.0f * (float(i) + 0.5f) / 2000.0f, r = std::sqrt(1.0f - y * y);
    const glm::vec3 n(r * std::cos(2.4f * float(i)), y, r * std::sin(2.4f * float(i)));
    worst = std::max(worst, std::abs(glm::dot(field.velocity(1.01f * kRadius * n), n)));
  }
  EXPECT_LT(worst, 0.08f);  // against a free-stream speed of 1
}

TEST(HairFlow, PanelsReproducePotentialFlowAroundASphere) {
  // Uniform flow U past a sphere: v_r = U cos(t) (1 - R^3/r^3), v_t = -U sin(t) (1 + R^3 / (2 r^3)).
  const BodyProxy proxy = sphereProxy(glm::vec3(0.0f), kRadius);
  const FlowField field = sphereFlow(proxy, downStream({0, 1, 0}), 500);
  for (int i = 0; i < 40; ++i) {
    const float t = 3.14159f * (float(i) + 0.5f) / 40.0f, phi = 0.7f * float(i);
    const glm::vec3 dir(std::sin(t) * std::cos(phi), std::cos(t), std::sin(t) * std::sin(phi));
    const float r = 1.4f * kRadius, k = std::pow(kRadius / r, 3.0f);
    const glm::vec3 thetaDir =
        glm::normalize(glm::vec3(std::cos(t) * std::cos(phi), -std::sin(t), std::cos(t) * std::sin(phi)));
    const glm::vec3 expected = std::cos(t) * (1.0f - k) * dir - std::sin(t) * (1.0f + 0.5f * k) * thetaDir;
    const glm::vec3 v = field.velocity(r * dir);
    EXPECT_LT(glm::length(v - expected), 0.06f) << "at polar angle " << t;
  }
}

// Streamlines seeded upstream of the head, traced with no push-out.
size_t pointsInsideSphere(const FlowField& field, const BodyProxy& traceProxy, float insideRadius) {
  TraceOptions raw;
  raw.pushOut = false;
  raw.perturb = false;
  std::vector<float> pts(3 * 64);
  size_t inside = 0;
  for (int i = 0; i < 60; ++i) {
    const float a = 2.39996f * float(i), rho = 0.012f + 0.1f * std::sqrt((float(i) + 0.5f) / 60.0f);
    const glm::vec3 seed(rho * std::cos(a), 0.3f, rho * std::sin(a));
    traceStreamline(field, traceProxy, seed, glm::vec3(0, -1, 0), 0.6f, 64, raw, pts.data());
    for (int k = 0; k < 64; ++k)
      inside += glm::length(glm::vec3(pts[3 * k], pts[3 * k + 1], pts[3 * k + 2])) < insideRadius;
  }
  return inside;
}

TEST(HairFlow, StreamlinesGoAroundTheSphereWithoutEnteringIt) {
  const BodyProxy proxy = sphereProxy(glm::vec3(0.0f), kRadius);
  const FlowField field = sphereFlow(proxy, downStream());
  EXPECT_EQ(pointsInsideSphere(field, proxy, kRadius), 0u);
  // The same seeds in the stream alone (no obstacle) do go through the head.
  FlowField free;
  free.setPrimitives(downStream(), glm::vec3(0.0f), 0.0f);
  EXPECT_GT(pointsInsideSphere(free, proxy, kRadius), 100u);
}

TEST(HairFlow, UniformStreamAloneAlignsStrandsFarFromTheHead) {
  const glm::vec3 d = glm::normalize(glm::vec3(0.4f, -1.0f, 0.3f));
  const BodyProxy proxy = sphereProxy(glm::vec3(0.0f), kRadius);
  const FlowField field = sphereFlow(proxy, downStream(d));
  TraceOptions options;
  options.perturb = false;
  std::vector<float> pts(3 * 32);
  for (const glm::vec3 seed :
       {glm::vec3(1.0f, 0.5f, 0.0f), glm::vec3(-0.8f, 0.0f, 0.9f), glm::vec3(0.0f, 1.2f, -1.0f)}) {
    traceStreamline(field, proxy, seed, glm::vec3(0, 1, 0), 0.3f, 32, options, pts.data());
    for (int k = 1; k < 32; ++k) {
      const glm::vec3 seg = glm::vec3(pts[3 * k], pts[3 * k + 1], pts[3 * k + 2]) -
                            glm::vec3(pts[3 * k - 3], pts[3 * k - 2], pts[3 * k - 1]);
      EXPECT_GT(glm::dot(glm::normalize(seg), d), 0.999f);
      EXPECT_NEAR(glm::length(seg), 0.3f / 31.0f, 1e-5f);
    }
  }
}

// Azimuth swept around the vertical axis by a strand from (0.03, 0, 0) down a
// vertical stream, with a vortex of `strength` on the axis.
float sweptAngle(float strength) {
  FlowPrimitives p = downStream();
  p.vortices.push_back({glm::vec3(0.0f, -0.15f, 0.0f), glm::vec3(0, -1, 0), strength, 0.05f});
  FlowField field;
  field.setPrimitives(p, glm::vec3(0.0f), 0.0f);
  TraceOptions options;
  options.perturb = false;
  std::vector<float> pts(3 * 64);
  traceStreamline(field, BodyProxy{}, glm::vec3(0.03f, 0.0f, 0.0f), glm::vec3(0, -1, 0), 0.3f, 64, options, pts.data());
  float total = 0.0f, previous = 0.0f;
  for (int k = 0; k < 64; ++k) {
    const float a = std::atan2(pts[3 * k + 2], pts[3 * k]);
    if (k > 0) total += std::remainder(a - previous, 6.2831853f);
    previous = a;
  }
  return total;
}

TEST(HairFlow, LoneVortexTurnsStrandsMoreWithStrength) {
  EXPECT_NEAR(sweptAngle(0.0f), 0.0f, 1e-4f);
  float last = 0.0f;
  for (float s : {0.1f, 0.2f, 0.4f, 0.8f}) {
    const float angle = std::abs(sweptAngle(s));
    EXPECT_GT(angle, last + 0.05f) << "strength " << s;
    last = angle;
  }
  EXPECT_GT(last, 2.0f);                                  // the strongest turns them by more than 115 degrees
  EXPECT_LT(sweptAngle(0.4f) * sweptAngle(-0.4f), 0.0f);  // the sign sets the sense
}

TEST(HairFlow, ProxyCellGridAgreesWithTestingEveryShape) {
  BodyProxy plain;
  plain.ellipsoids.push_back({glm::vec3(0.0f, 1.6f, 0.0f),
                              glm::mat3(glm::rotate(glm::mat4(1.0f), 0.4f, glm::vec3(1, 0, 1))),
                              glm::vec3(0.07f, 0.11f, 0.03f)});
  plain.capsules.push_back({glm::vec3(0, 1.5f, 0), glm::vec3(0.2f, 1.3f, 0), 0.04f});
  plain.capsules.push_back({glm::vec3(0, 1.2f, 0), glm::vec3(0, 1.45f, 0), 0.12f});
  BodyProxy gridded = plain;
  gridded.updateBounds();
  for (int i = 0; i < 200000; ++i) {
    const glm::vec3 p(0.3f * std::sin(1.37f * i), 1.1f + 0.7f * std::fmod(0.6180339f * i, 1.0f),
                      0.3f * std::cos(0.91f * i));
    for (float margin : {0.0f, 0.002f, 0.01f}) ASSERT_EQ(plain.contains(p, margin), gridded.contains(p, margin)) << i;
    glm::vec3 a = p, b = p;
    plain.pushOut(a, 0.002f);
    gridded.pushOut(b, 0.002f);
    ASSERT_EQ(a, b) << i;
    ASSERT_FALSE(plain.contains(b, 0.0015f)) << i;
  }
}

TEST(HairFlow, PushOutKeepsPointsOutsideEveryShape) {
  BodyProxy proxy = sphereProxy(glm::vec3(0.0f), 0.1f);
  proxy.capsules.push_back({glm::vec3(0, -0.05f, 0), glm::vec3(0, -0.3f, 0), 0.05f});
  proxy.updateBounds();
  for (int i = 0; i < 1000; ++i) {
    glm::vec3 p(std::sin(1.3f * i) * 0.12f, -0.3f + 0.45f * float(i) / 1000.0f, std::cos(0.7f * i) * 0.1f);
    proxy.pushOut(p, 0.001f);
    EXPECT_FALSE(proxy.contains(p)) << i;
  }
}

}  // namespace
}  // namespace mq
