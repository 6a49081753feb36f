// Roots, guides and children, hairstyles and their JSON.
#include <gtest/gtest.h>

#include "core/character/default_mannequin.h"
#include "core/hair/character_groom.h"
#include "core/hair/hair_groom.h"
#include "core/hair/hairstyle_json.h"
#include "core/hair/root_sampling.h"
#include "core/hair/strand_tracer.h"
#include "core/scene/scene_document.h"
#include "core/util/error.h"
#include "hair_test_util.h"

namespace mq {
namespace {

TEST(HairRoots, PoissonDiskMinimumDistanceAndCount) {
  const ScalpSurface scalp = test::sphereScalp(glm::vec3(0.0f, 1.6f, 0.0f), 0.1f, -0.2f);
  for (size_t count : {500u, 5000u, 20000u}) {
    const HairRoots roots = sampleRoots(scalp, count, 7);
    ASSERT_EQ(roots.size(), count);
    ASSERT_GT(roots.minDistance, 0.0f);
    // Brute force over all pairs (sorted by x to prune).
    std::vector<glm::vec3> p(count);
    for (size_t i = 0; i < count; ++i) p[i] = roots.position(i);
    std::sort(p.begin(), p.end(), [](auto& a, auto& b) { return a.x < b.x; });
    float closest = 1e30f;
    for (size_t i = 0; i < count; ++i)
      for (size_t j = i + 1; j < count && p[j].x - p[i].x < roots.minDistance * 2; ++j)
        closest = std::min(closest, glm::length(p[j] - p[i]));
    EXPECT_GE(closest, roots.minDistance * 0.9999f) << count;
    // And the radius is no mere formality: it is at least half of a hexagonal packing's spacing.
    EXPECT_GT(roots.minDistance, 0.5f * std::sqrt(scalp.area() / float(count)));
    // On the scalp.
    for (size_t i = 0; i < count; ++i)
      EXPECT_NEAR(glm::length(roots.position(i) - glm::vec3(0.0f, 1.6f, 0.0f)), 0.1f, 2e-3f);
  }
}

TEST(HairRoots, DensityGivesTheCount) {
  const ScalpSurface scalp = test::sphereScalp(glm::vec3(0.0f), 0.1f, 0.0f);
  // A hemisphere of radius 10 cm: 2 pi 100 cm^2.
  EXPECT_NEAR(scalp.area() * 1e4f, 628.3f, 3.0f);
  EXPECT_NEAR(double(rootCountForDensity(scalp, 100.0f, 1000000)), 62832.0, 400.0);
  EXPECT_EQ(rootCountForDensity(scalp, 100.0f, 5000), 5000u);
}

HairGroom sphereGroom() {
  return HairGroom(test::sphereScalp(glm::vec3(0.0f, 1.6f, 0.0f), 0.1f, -0.1f),
                   sphereProxy(glm::vec3(0.0f, 1.6f, 0.0f), 0.099f), 200);
}

TEST(HairGroom, RequestedCountSameSeedSameStrands) {
  HairStyle style = builtinHairStyle("wavy");
  style.guideCount = 300;
  HairGroom a = sphereGroom(), b = sphereGroom();
  a.grow(style, 3000);
  b.grow(style, 3000);
  EXPECT_EQ(a.strands().strandCount(), 3000u);
  EXPECT_EQ(a.guideCount(), 300u);
  EXPECT_EQ(a.strands().pointsPerStrand, style.pointsPerStrand);
  EXPECT_EQ(a.strands().points, b.strands().points);
  EXPECT_EQ(a.countPointsInside(), 0u);
  style.seed = 2;
  b.grow(style, 3000);
  EXPECT_NE(a.strands().points, b.strands().points);
}

TEST(HairGroom, GuidesFirstThenChildrenThatFollowThem) {
  HairStyle style = builtinHairStyle("long_straight");
  style.guideCount = 200;
  HairGroom groom = sphereGroom();
  groom.grow(style, 2000);
  const Strands& s = groom.strands();
  for (size_t i = 0; i < 200; ++i) EXPECT_EQ(s.guideOf[i], -1);
  std::vector<float> tipGaps;
  for (size_t i = 200; i < 2000; ++i) {
    ASSERT_GE(s.guideOf[i], 0);
    ASSERT_LT(s.guideOf[i], 200);
    // A child's tip stays near its guide's tip (it follows, it does not wander off).
    const int g = s.guideOf[i];
    const int last = s.pointsPerStrand - 1;
    const glm::vec3 childTip(s.strand(i)[3 * last], s.strand(i)[3 * last + 1], s.strand(i)[3 * last + 2]);
    const glm::vec3 guideTip(s.strand(g)[3 * last], s.strand(g)[3 * last + 1], s.strand(g)[3 * last + 2]);
    tipGaps.push_back(glm::length(childTip - guideTip));
  }
  std::sort(tipGaps.begin(), tipGaps.end());
  EXPECT_LT(tipGaps[tipGaps.size() / 2], 0.03f);  // 45 cm hair
  EXPECT_LT(tipGaps.back(), 0.25f);
  // The hair falls: tips well below roots on average.
  double drop = 0.0;
  for (size_t i = 0; i < 2000; ++i) drop += s.strand(i)[1] - s.strand(i)[3 * (s.pointsPerStrand - 1) + 1];
  EXPECT_GT(drop / 2000.0, 0.15);
}

TEST(HairGroom, DefaultMannequinHairStaysOutOfTheBody) {
  const Character mannequin = makeDefaultMannequin();
  std::unique_ptr<HairGroom> groom = makeCharacterGroom(mannequin, ScalpRegion{});
  EXPECT_GT(groom->scalp().area(), 0.01f);  // more than 100 cm^2 of scalp
  EXPECT_GT(groom->proxy().capsules.size(), 2u);
  for (const std::string& name : builtinHairStyleNames()) {
    HairStyle style = builtinHairStyle(name);
    style.guideCount = 400;
    groom->grow(style, 4000);
    EXPECT_EQ(groom->strands().strandCount(), 4000u) << name;
    EXPECT_EQ(groom->countPointsInside(), 0u) << name;
    // Guides keep a fixed segment length (their rest lengths for the
    // dynamics), but where a push-out bends them at the body.
    const Strands& s = groom->strands();
    size_t off = 0, total = 0;
    for (size_t g = 0; g < groom->guideCount(); ++g) {
      std::vector<float> lengths;
      for (int k = 1; k < s.pointsPerStrand; ++k) {
        const float* p = s.strand(g) + 3 * k;
        lengths.push_back(glm::length(glm::vec3(p[0], p[1], p[2]) - glm::vec3(p[-3], p[-2], p[-1])));
      }
      std::vector<float> sorted = lengths;
      std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
      const float median = sorted[sorted.size() / 2];
      for (float len : lengths) {
        ASSERT_GT(len, 0.8f * median) << name;
        ASSERT_LT(len, 1.01f * median) << name;
        off += std::abs(len - median) > 1e-3f * median;
        ++total;
      }
    }
    EXPECT_LT(off, total / 100) << name;  // under 1% of the segments differ from the strand's first
  }
}

TEST(HairGroom, MannequinStreamlinesStayOutsideTheHeadWithoutPushOut) {
  // The raw streamlines of the obstacle flow (no push-out, no noise) from
  // the mannequin's guide roots: the panel method alone keeps them out of
  // the head ellipsoid, but for a sliver at the scalp (1 mm).
  const Character mannequin = makeDefaultMannequin();
  std::unique_ptr<HairGroom> groom = makeCharacterGroom(mannequin, ScalpRegion{});
  HairStyle style = builtinHairStyle("long_straight");
  style.guideCount = 300;
  groom->grow(style, 300);
  TraceOptions raw;
  raw.pushOut = false;
  raw.perturb = false;
  BodyProxy head;
  head.ellipsoids.push_back(groom->proxy().ellipsoids[0]);
  std::vector<float> pts(3 * 32);
  size_t inside = 0;
  for (size_t g = 0; g < groom->guideRoots().size(); ++g) {
    traceStreamline(groom->flow(), head, groom->guideRoots().position(g), groom->guideRoots().normal(g), 0.4f, 32, raw,
                    pts.data());
    for (int k = 1; k < 32; ++k) inside += head.contains({pts[3 * k], pts[3 * k + 1], pts[3 * k + 2]}, -0.001f);
  }
  EXPECT_EQ(inside, 0u);
}

TEST(HairStyleJson, RoundTripAndOverrides) {
  for (const std::string& name : builtinHairStyleNames()) {
    const HairStyle style = builtinHairStyle(name);
    const nlohmann::json j = toJson(style);
    EXPECT_EQ(toJson(hairStyleFromJson(j)), j) << name;
  }
  const nlohmann::json section = nlohmann::json::parse(R"({
    "style": {"preset": "bob", "length": 0.25, "vortices": [{"position": [0, 0.1, 0], "axis": [0, 1, 0], "strength": 0.3, "radius": 0.04}]},
    "scalp": {"kind": "bone_cone", "bone": "head", "axis": [0, 1, 0.2], "angle": 65},
    "strands": 1234})");
  const HairSection s = hairSectionFromJson(section);
  EXPECT_EQ(s.style.name, "bob");
  EXPECT_FLOAT_EQ(s.style.length, 0.25f);
  ASSERT_EQ(s.style.primitives.vortices.size(), 1u);
  EXPECT_FLOAT_EQ(s.style.primitives.vortices[0].radius, 0.04f);
  EXPECT_EQ(s.style.primitives.sources.size(), builtinHairStyle("bob").primitives.sources.size());
  EXPECT_EQ(s.scalp.kind, ScalpRegion::Kind::BoneCone);
  EXPECT_FLOAT_EQ(s.scalp.angleDegrees, 65.0f);
  EXPECT_EQ(s.strands, 1234u);
  EXPECT_EQ(toJson(hairSectionFromJson(toJson(s))), toJson(s));
  EXPECT_THROW(hairStyleFromJson(nlohmann::json("mohawk")), Error);
  EXPECT_THROW(hairStyleFromJson(nlohmann::json::parse(R"({"length": "long"})")), Error);
  EXPECT_THROW(scalpRegionFromJson(nlohmann::json::parse(R"({"kind": "painted"})")), Error);
}

TEST(HairStyleJson, ShippedHairScenesHoldTheBuiltInStyles) {
  for (const std::string& name : builtinHairStyleNames()) {
    const std::string path = std::string(MANNEQUIN_SOURCE_DIR) + "/resources/scenes/hair_" + name + ".json";
    const SceneDocument doc = loadSceneDocument(path);
    EXPECT_EQ(doc.character, "default") << path;
    const HairSection section = hairSectionFromJson(doc.hair);
    EXPECT_EQ(toJson(section.style), toJson(builtinHairStyle(name))) << path;
    EXPECT_EQ(section.scalp.kind, ScalpRegion::Kind::Tagged) << path;
  }
}

// A face-list scalp keeps the head bone it was found with: an imported
// character's head is not called "head" (CesiumMan's is not), and a saved
// scene must grow on it again.
TEST(HairStyleJson, AFaceScalpKeepsItsHeadBone) {
  ScalpRegion region;
  region.kind = ScalpRegion::Kind::Faces;
  region.bone = "Skeleton_neck_joint_2";
  region.mesh = 1;
  region.faces = {3, 4, 5};
  const ScalpRegion back = scalpRegionFromJson(toJson(region));
  EXPECT_EQ(back.bone, "Skeleton_neck_joint_2");
  EXPECT_EQ(back.mesh, 1);
  EXPECT_EQ(back.faces, region.faces);
  // Older files, without it: the default head bone.
  EXPECT_EQ(scalpRegionFromJson(nlohmann::json::parse(R"({"kind": "faces", "faces": [1]})")).bone, ScalpRegion{}.bone);
}

}  // namespace
}  // namespace mq
