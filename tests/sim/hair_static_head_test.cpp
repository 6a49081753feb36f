// Hair simulated on a static head scan: the colliders carry the scan's own
// surface (a distance field), so strands that settle under gravity rest on
// the scan, not on the smaller ellipsoid inside it.
#include <gtest/gtest.h>

#include "core/hair/character_groom.h"
#include "core/hair/hairstyle_json.h"
#include "core/static_head_util.h"
#include "sim/hair/child_follow.h"
#include "sim/hair/hair_bake.h"

namespace mq {
namespace {

TEST(HairStaticHead, SettledGuidesStayOutOfTheScan) {
  const Character head = test::headScan();
  HairSection section;
  section.style = builtinHairStyle("long_straight");
  section.style.guideCount = 300;
  section.fitToHead = true;
  std::unique_ptr<HairGroom> groom = makeSectionGroom(head, section);
  groom->grow(section.style, 300);
  const Strands guides = leadingStrands(groom->strands(), groom->guideCount());

  const HairRig rig = HairRig::fromProxy(head, groom->proxy());
  ASSERT_TRUE(rig.body.surface);  // no bones: the scan is a fixed collider
  HairSimParams params;           // the defaults: softer than a character's, the hair sags onto the head
  params.globalRange = 0.0f;
  HairSimulator sim(params);
  sim.setRest(guides);
  const PosedHairColliders body = rig.body.posed({}, params.collisionMargin);
  for (int step = 0; step < 120; ++step) sim.step(1.0f / 60.0f, glm::mat4(1.0f), &body);

  const test::OpenMeshInside inside(head.meshes[0]);
  const std::vector<float>& now = sim.positions();
  size_t pointsInside = 0, moved = 0;
  for (size_t k = 0; k < now.size(); k += 3) {
    if ((k / 3) % size_t(sim.pointsPerStrand()) == 0) continue;  // roots are on the scan
    const glm::vec3 p(now[k], now[k + 1], now[k + 2]);
    pointsInside += inside.contains(p);
    moved += glm::length(p - glm::vec3(guides.points[k], guides.points[k + 1], guides.points[k + 2])) > 1e-3f;
  }
  EXPECT_EQ(pointsInside, 0u);
  EXPECT_GT(moved, now.size() / 3 / 10);  // gravity did move them: the check is not of the rest shape
}

}  // namespace
}  // namespace mq
