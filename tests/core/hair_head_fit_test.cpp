// Built-in hairstyles fitted to other heads, and the automatic scalp of
// imported characters.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/character/default_mannequin.h"
#include "core/character/posed_character.h"
#include "core/hair/character_groom.h"
#include "core/hair/head_fit.h"
#include "core/io/character_import.h"
#include "hair_test_util.h"

namespace mq {
namespace {

const glm::vec3 kCentre(0.0f, 1.6f, 0.0f);

struct Extent {
  glm::vec3 lo{1e30f}, hi{-1e30f};
  glm::vec3 size() const { return hi - lo; }
};

Extent extentOf(const Strands& strands) {
  Extent e;
  for (size_t k = 0; k < strands.points.size(); k += 3) {
    const glm::vec3 p(strands.points[k], strands.points[k + 1], strands.points[k + 2]);
    e.lo = glm::min(e.lo, p);
    e.hi = glm::max(e.hi, p);
  }
  return e;
}

// Mean distance from the head centre of the strands' tips, and of all points.
float meanTipDistance(const Strands& strands) {
  double sum = 0.0;
  for (size_t s = 0; s < strands.strandCount(); ++s) {
    const float* tip = strands.strand(s) + 3 * (strands.pointsPerStrand - 1);
    sum += glm::length(glm::vec3(tip[0], tip[1], tip[2]) - kCentre);
  }
  return float(sum / double(strands.strandCount()));
}

float meanPointDistance(const Strands& strands) {
  double sum = 0.0;
  for (size_t k = 0; k < strands.points.size(); k += 3)
    sum += glm::length(glm::vec3(strands.points[k], strands.points[k + 1], strands.points[k + 2]) - kCentre);
  return float(sum / double(strands.points.size() / 3));
}

HairGroom sphereGroom(float radius) {
  return HairGroom(test::sphereScalp(kCentre, radius, -0.1f), sphereProxy(kCentre, radius * 0.99f), 200);
}

TEST(HairHeadFit, ScaledStyleScalesLengthsPositionsAndDensity) {
  const HairStyle bob = builtinHairStyle("bob");
  const HairStyle big = scaledHairStyle(bob, 2.0f);
  EXPECT_FLOAT_EQ(big.length, 2.0f * bob.length);
  EXPECT_FLOAT_EQ(big.density, bob.density / 4.0f);
  ASSERT_EQ(big.primitives.sources.size(), bob.primitives.sources.size());
  for (size_t i = 0; i < bob.primitives.sources.size(); ++i) {
    EXPECT_FLOAT_EQ(big.primitives.sources[i].position.y, 2.0f * bob.primitives.sources[i].position.y);
    EXPECT_FLOAT_EQ(big.primitives.sources[i].radius, 2.0f * bob.primitives.sources[i].radius);
  }
  EXPECT_EQ(big.guideCount, bob.guideCount);
  EXPECT_EQ(big.pointsPerStrand, bob.pointsPerStrand);
}

// The same built-in on a head twice the size: fitted, the groom is the same
// shape twice as big; unfitted it would be nearly as big as on the small head.
TEST(HairHeadFit, FittedGroomIsProportionalToTheHead) {
  for (const char* name : {"bob", "long_straight"}) {
    const float r = 0.09f;
    HairGroom small = sphereGroom(r), large = sphereGroom(2.0f * r);
    const HairStyle style = builtinHairStyle(name);
    small.grow(fitHairStyleToHead(style, small.proxy()), 4000);
    large.grow(fitHairStyleToHead(style, large.proxy()), 4000);
    EXPECT_EQ(small.countPointsInside(), 0u) << name;
    EXPECT_EQ(large.countPointsInside(), 0u) << name;
    EXPECT_NEAR(meanTipDistance(large.strands()) / meanTipDistance(small.strands()), 2.0f, 0.2f) << name;
    EXPECT_NEAR(meanPointDistance(large.strands()) / meanPointDistance(small.strands()), 2.0f, 0.2f) << name;
    // Hair below the head's centre reaches proportionally as far.
    const float dropSmall = kCentre.y - extentOf(small.strands()).lo.y,
                dropLarge = kCentre.y - extentOf(large.strands()).lo.y;
    EXPECT_NEAR(dropLarge / dropSmall, 2.0f, 0.2f) << name;
    // Not fitted, the same numbers on the large head: much less than twice as far.
    HairGroom unfitted = sphereGroom(2.0f * r);
    unfitted.grow(style, 4000);
    EXPECT_LT(meanTipDistance(unfitted.strands()) / meanTipDistance(small.strands()), 1.6f) << name;
  }
}

TEST(HairHeadFit, DefaultMannequinIsTheReferenceHead) {
  const Character mannequin = makeDefaultMannequin();
  EXPECT_EQ(mannequin.skeleton.bone(findHeadBone(mannequin)).name, "head");
  HairSection section;
  section.style = builtinHairStyle("wavy");
  std::unique_ptr<HairGroom> groom = makeSectionGroom(mannequin, section);
  EXPECT_NEAR(headSize(groom->proxy()), kReferenceHeadSize, 1e-3f * kReferenceHeadSize);
  EXPECT_FLOAT_EQ(section.style.length, builtinHairStyle("wavy").length);  // unchanged on the reference head
  EXPECT_EQ(section.scalp.kind, ScalpRegion::Kind::Tagged);
}

// An imported character without scalp tags or a "head" bone (CesiumMan):
// the head bone is found by height, the scalp is the top and back of its
// head, and a built-in grows to a size proportional to that head.
TEST(HairHeadFit, ImportedCharacterGetsAScalpAndAFittedStyle) {
  const std::string path = std::string(MANNEQUIN_SHARED_DIR) + "/assets/characters/CesiumMan/glTF-Binary/CesiumMan.glb";
  ASSERT_TRUE(std::filesystem::exists(path)) << path;
  const Character cesium = importCharacter(path);
  const int head = findHeadBone(cesium);
  ASSERT_GE(head, 0);
  EXPECT_EQ(cesium.skeleton.bone(head).name, "Skeleton_neck_joint_2");

  HairSection section;
  section.style = builtinHairStyle("bob");
  std::unique_ptr<HairGroom> groom = makeSectionGroom(cesium, section);
  EXPECT_EQ(section.scalp.kind, ScalpRegion::Kind::Faces);
  groom->grow(section.style, 6000);
  ASSERT_EQ(groom->strands().strandCount(), 6000u);
  EXPECT_EQ(groom->countPointsInside(), 0u);

  // Roots on the character's rest mesh, on faces of the head, none on the face (+Z).
  PosedCharacter rest;
  rest.evaluate(cesium, -1, 0.0f, nullptr, nullptr);
  const Mesh& mesh = cesium.meshes[section.scalp.mesh];
  const std::vector<float>& positions = rest.meshes()[section.scalp.mesh].positions;
  const Strands& strands = groom->strands();
  const glm::vec3 centre = groom->proxy().headCenter();
  for (size_t s = 0; s < strands.strandCount(); s += 7) {
    const glm::vec3 root(strands.strand(s)[0], strands.strand(s)[1], strands.strand(s)[2]);
    float nearest = 1e30f;
    size_t vertex = 0;
    for (size_t v = 0; v < mesh.vertexCount(); ++v) {
      const float d = glm::length(root - glm::vec3(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]));
      if (d < nearest) nearest = d, vertex = v;
    }
    ASSERT_LT(nearest, 0.05f) << "strand " << s;
    EXPECT_EQ(dominantBone(mesh, vertex), head) << "strand " << s;
    const glm::vec3 out = glm::normalize(root - centre);
    EXPECT_LT(out.z, 0.85f) << "strand " << s << " grows from the face";
  }

  // Proportional to the head: the bob's drop below the head centre, in head
  // sizes, as on the default mannequin.
  const Character mannequin = makeDefaultMannequin();
  HairSection reference;
  reference.style = builtinHairStyle("bob");
  std::unique_ptr<HairGroom> referenceGroom = makeSectionGroom(mannequin, reference);
  referenceGroom->grow(reference.style, 6000);
  const float k = headSize(groom->proxy()) / kReferenceHeadSize;
  EXPECT_GT(k, 1.2f);  // CesiumMan's head is bigger than the mannequin's
  EXPECT_NEAR(section.style.length, k * reference.style.length, 1e-4f);
  const float drop = (centre.y - extentOf(strands).lo.y) / headSize(groom->proxy());
  const float referenceDrop =
      (referenceGroom->proxy().headCenter().y - extentOf(referenceGroom->strands()).lo.y) / kReferenceHeadSize;
  EXPECT_NEAR(drop / referenceDrop, 1.0f, 0.3f);
}

}  // namespace
}  // namespace mq
