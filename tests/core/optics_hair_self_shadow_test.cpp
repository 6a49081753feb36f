// Hair self-shadowing (core/optics/hair_self_shadow.h), without a display:
// light falls off with depth into the hair from the side of the light, and
// opacity shadow maps converge to the exact count.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/hair_test_util.h"
#include "core/optics/hair_self_shadow.h"

namespace mq {
namespace {

using test::combedStrands;

// A slab of parallel horizontal strands stacked along y, lit from above: the
// top layer is lit, each layer below gets less light; lit from below, the
// order reverses. Both self-shadowing methods must behave so.
void expectSlabDarkensWithDepth(optics::HairShadowMethod method) {
  Strands strands;
  strands.pointsPerStrand = 16;
  for (int layer = 0; layer < 10; ++layer)
    for (int row = 0; row < 20; ++row)
      for (int i = 0; i < 16; ++i)
        strands.points.insert(strands.points.end(), {0.01f * float(i), -0.005f * float(layer), 0.002f * float(row)});
  optics::HairShadowSettings settings;
  settings.minShadow = 0.0f;
  settings.perStrand = 0.04f;  // weak, so the deepest layers do not all saturate near 0
  settings.method = method;
  const std::vector<float> shadow = optics::hairSelfShadow(strands, {0.0f, 1.0f, 0.0f}, settings);
  auto layerMean = [&](int layer) {
    double sum = 0.0;
    for (int row = 0; row < 20; ++row)
      for (int i = 2; i < 14; ++i) sum += shadow[(layer * 20 + row) * 16 + i];
    return sum / (20 * 12);
  };
  EXPECT_GT(layerMean(0), 0.95);
  for (int layer = 1; layer < 10; ++layer) EXPECT_LT(layerMean(layer), layerMean(layer - 1) - 0.02) << layer;
  EXPECT_LT(layerMean(9), 0.5);
  const std::vector<float> fromBelow = optics::hairSelfShadow(strands, {0.0f, -1.0f, 0.0f}, settings);
  EXPECT_GT(fromBelow[(9 * 20 + 10) * 16 + 8], 0.95f);
  EXPECT_LT(fromBelow[(0 * 20 + 10) * 16 + 8], 0.5f);
}

TEST(HairSelfShadow, DarkensWithDepthIntoTheHair) { expectSlabDarkensWithDepth(optics::HairShadowMethod::PointCount); }

// Opacity shadow maps: the same layered slab, the same darkening with depth.
TEST(HairSelfShadow, OpacityMapsDarkenWithDepthLikeTheExactCount) {
  expectSlabDarkensWithDepth(optics::HairShadowMethod::OpacityMaps);
}

// On a real groom the maps approach the exact count, closer with more maps.
TEST(HairSelfShadow, OpacityMapsConvergeToTheExactCount) {
  const Strands strands = combedStrands(6000, 24, 0.3f);
  const glm::vec3 light = glm::normalize(glm::vec3(0.3f, 1.0f, 0.4f));
  optics::HairShadowSettings exact;
  const std::vector<float> reference = optics::hairSelfShadow(strands, light, exact);
  auto meanError = [&](int maps) {
    optics::HairShadowSettings osm = exact;
    osm.method = optics::HairShadowMethod::OpacityMaps;
    osm.opacityMapCount = maps;
    const std::vector<float> s = optics::hairSelfShadow(strands, light, osm);
    double sum = 0.0;
    for (size_t k = 0; k < s.size(); ++k) sum += std::abs(s[k] - reference[k]);
    return sum / double(s.size());
  };
  double spread = 0.0;  // how much the exact term varies: the errors must be small against it
  double mean = 0.0;
  for (float r : reference) mean += r / double(reference.size());
  for (float r : reference) spread += std::abs(r - mean) / double(reference.size());
  ASSERT_GT(spread, 0.05);
  const double coarse = meanError(4), fine = meanError(64);
  EXPECT_LT(fine, 0.25 * spread);
  EXPECT_LT(fine, coarse);
}

}  // namespace
}  // namespace mq
