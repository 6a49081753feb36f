// Hair on meshes without bones: the MakeHuman head scan of ../shared/assets
// (an OBJ in decimetres) and the mannequin written out as a static OBJ.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "core/character/default_mannequin.h"
#include "core/character/posed_character.h"
#include "core/hair/character_groom.h"
#include "core/hair/hairstyle_json.h"
#include "core/hair/scalp_paint.h"
#include "core/hair/static_head.h"
#include "core/io/character_import.h"
#include "static_head_util.h"

namespace mq {
namespace {

using test::headScan;
using test::OpenMeshInside;

// Distance from p to triangle abc (the closest point by Voronoi regions).
float triangleDistance(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
  const glm::vec3 n = glm::cross(b - a, c - a);
  const float area2 = glm::dot(n, n);
  if (area2 > 0.0f) {
    const glm::vec3 q = p - n * (glm::dot(p - a, n) / area2);  // projection on the plane
    const float u = glm::dot(glm::cross(c - b, q - b), n), v = glm::dot(glm::cross(a - c, q - c), n),
                w = glm::dot(glm::cross(b - a, q - a), n);
    if (u >= 0.0f && v >= 0.0f && w >= 0.0f) return glm::length(p - q);
  }
  auto segment = [&](const glm::vec3& s, const glm::vec3& e) {
    const float t = glm::clamp(glm::dot(p - s, e - s) / std::max(glm::dot(e - s, e - s), 1e-20f), 0.0f, 1.0f);
    return glm::length(p - (s + t * (e - s)));
  };
  return std::min({segment(a, b), segment(b, c), segment(c, a)});
}

float surfaceDistance(const Mesh& mesh, const glm::vec3& p) {
  float best = 1e30f;
  for (size_t t = 0; t < mesh.triangleCount(); ++t)
    best = std::min(best,
                    triangleDistance(p, mesh.position(mesh.triangles[3 * t]), mesh.position(mesh.triangles[3 * t + 1]),
                                     mesh.position(mesh.triangles[3 * t + 2])));
  return best;
}

TEST(StaticHead, AHeadAloneIsAllHeadAndABodyOnlyAtItsTop) {
  const Character head = headScan();
  ASSERT_EQ(head.skeleton.boneCount(), 0);
  const auto flags = staticHeadVertices(head);
  EXPECT_EQ(std::count(flags[0].begin(), flags[0].end(), 1), long(head.meshes[0].vertexCount()));

  Character body = makeDefaultMannequin();
  body.skeleton = Skeleton();  // the same surface as a static mesh
  for (Mesh& m : body.meshes) m.skin = SkinBinding();
  body.clips.clear();
  const auto bodyFlags = staticHeadVertices(body);
  const Mesh& skin = body.meshes[0];
  float lowest = 1e30f;
  size_t count = 0;
  for (size_t v = 0; v < skin.vertexCount(); ++v)
    if (bodyFlags[0][v]) {
      lowest = std::min(lowest, skin.position(v).y);
      ++count;
    }
  EXPECT_GT(count, 100u);
  EXPECT_LT(count, skin.vertexCount() / 5);
  EXPECT_GT(lowest, 1.45f);  // the mannequin is 1.75 m tall: nothing below the chin
}

// Every built-in style grows on the scan: roots on its surface, on the top
// and back of the head, none on the face; no strand point inside the scan
// (the hair flows around an ellipsoid fitted to it, and is kept out of the
// scan itself by its distance field).
TEST(StaticHead, HairGrowsOnTheHeadScan) {
  const Character head = headScan();
  const Mesh& mesh = head.meshes[0];
  const OpenMeshInside inside(mesh);
  for (const std::string& name : builtinHairStyleNames()) {
    HairSection section;
    section.style = builtinHairStyle(name);
    section.style.guideCount = 300;
    section.fitToHead = true;
    section.strands = 3000;
    std::unique_ptr<HairGroom> groom = makeSectionGroom(head, section);
    groom->grow(section.style, section.strands);
    const Strands& s = groom->strands();
    ASSERT_EQ(s.strandCount(), 3000u) << name;
    float worstRoot = 0.0f;
    size_t pointsInside = 0, pointsTested = 0;
    for (size_t k = 0; k < s.strandCount(); ++k) {
      const float* p = s.strand(k);
      if (k % 10 == 0) worstRoot = std::max(worstRoot, surfaceDistance(mesh, {p[0], p[1], p[2]}));
      for (int i = 1; i < s.pointsPerStrand; i += 3, ++pointsTested)
        pointsInside += inside.contains({p[3 * i], p[3 * i + 1], p[3 * i + 2]});
    }
    EXPECT_LT(worstRoot, 0.01f) << name;  // on the scan, as the CLI tests hold the mannequin's roots
    EXPECT_EQ(pointsInside, 0u) << name;
    // The roots cover the top and back of the head, down to the nape (the
    // scan, 0.23 m tall, goes down to the neck).
    float lowestRoot = 1e30f;
    for (size_t k = 0; k < s.strandCount(); ++k) lowestRoot = std::min(lowestRoot, s.strand(k)[1]);
    Aabb box = boundsOf(mesh.positions);
    EXPECT_GT(lowestRoot, box.min.y + 0.25f * (box.max.y - box.min.y)) << name;
    // The hairline stays above the eyes: the front of the face (where the
    // scan reaches farthest forward) has no root below the forehead's top
    // half.
    const float eyes = box.min.y + 0.45f * (box.max.y - box.min.y);
    size_t rootsOnFace = 0;
    for (size_t k = 0; k < s.strandCount(); ++k) {
      const float* root = s.strand(k);
      rootsOnFace += root[2] > box.max.z - 0.05f && root[1] < eyes + 0.04f;
    }
    EXPECT_EQ(rootsOnFace, 0u) << name;
    std::printf("%s: %zu of %zu strand points inside the scan\n", name.c_str(), pointsInside, pointsTested);
  }
}

// The brush: dabs add the faces near the cursor, erasing takes them away,
// and hair grows on what was painted.
TEST(ScalpPaint, DabsAddAndEraseFacesAndHairGrowsThere) {
  const Character head = headScan();
  const Mesh& mesh = head.meshes[0];
  // The top of the scan: its highest vertex.
  glm::vec3 top = mesh.position(0);
  for (size_t v = 1; v < mesh.vertexCount(); ++v)
    if (mesh.position(v).y > top.y) top = mesh.position(v);
  const std::vector<std::vector<float>> shown = {mesh.positions};
  ASSERT_EQ(meshUnderBrush(shown, top), 0);

  ScalpRegion region;
  region.kind = ScalpRegion::Kind::Faces;
  region = paintScalp(region, 0, mesh.triangles, mesh.positions, top, 0.03f, false);
  ASSERT_GT(region.faces.size(), 10u);
  for (uint32_t f : region.faces) {
    glm::vec3 centre(0.0f);
    for (int k = 0; k < 3; ++k) centre += mesh.position(mesh.triangles[3 * f + k]) / 3.0f;
    EXPECT_LE(glm::length(centre - top), 0.03f + 1e-6f);
  }
  const glm::vec3 back = top + glm::vec3(0.0f, -0.03f, -0.05f);  // a second dab behind
  const ScalpRegion twoDabs = paintScalp(region, 0, mesh.triangles, mesh.positions, back, 0.03f, false);
  EXPECT_GT(twoDabs.faces.size(), region.faces.size());
  const ScalpRegion erased = paintScalp(twoDabs, 0, mesh.triangles, mesh.positions, top, 0.03f, true);
  EXPECT_EQ(erased.faces.size(), twoDabs.faces.size() - region.faces.size());  // the first dab's faces, erased
  for (uint32_t f : erased.faces) EXPECT_FALSE(std::binary_search(region.faces.begin(), region.faces.end(), f));

  HairSection section;
  section.style = builtinHairStyle("bob");
  section.style.guideCount = 100;
  section.fitToHead = true;
  section.scalp = twoDabs;
  section.scalpGiven = true;
  std::unique_ptr<HairGroom> groom = makeSectionGroom(head, section);
  groom->grow(section.style, 1000);
  const float scalpArea = groom->scalp().area();
  EXPECT_GT(scalpArea, 0.002f);  // two dabs of 3 cm: a few tens of cm^2
  EXPECT_LT(scalpArea, 0.01f);
  for (size_t k = 0; k < groom->strands().strandCount(); ++k) {
    const float* root = groom->strands().strand(k);
    EXPECT_LT(std::min(glm::length(glm::vec3(root[0], root[1], root[2]) - top),
                       glm::length(glm::vec3(root[0], root[1], root[2]) - back)),
              0.045f);
  }
}

// A region of another kind becomes the same faces, ready for the brush.
TEST(ScalpPaint, TheMannequinsTaggedScalpAsFacesIsTheSameScalp) {
  const Character mannequin = makeDefaultMannequin();
  const ScalpRegion tagged;
  const ScalpRegion faces = scalpAsFaces(mannequin, tagged);
  EXPECT_EQ(faces.kind, ScalpRegion::Kind::Faces);
  EXPECT_GT(faces.faces.size(), 100u);
  EXPECT_NEAR(extractScalp(mannequin, faces).area(), extractScalp(mannequin, tagged).area(), 1e-6f);
}

}  // namespace
}  // namespace mq
