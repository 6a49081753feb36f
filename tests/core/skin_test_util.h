#pragma once
// Small characters with closed-form skinning behaviour, shared by the
// skinning tests: a two-bone chain along +Y, a tube skinned to it, its bend,
// and the threading check.

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "core/character/posed_character.h"
#include "core/skinning/skin_metrics.h"
#include "core/util/thread_pool.h"

namespace mq {

// Two bones along +Y: root at the origin, child 1 m up.
inline Skeleton twoBoneChain() {
  Skeleton s;
  Bone root;
  root.name = "root";
  s.addBone(root);
  Bone child;
  child.name = "child";
  child.parent = 0;
  child.rest.translation = {0, 1, 0};
  s.addBone(child);
  return s;
}

// A tube of radius 0.2 from y = 0 to y = 2 around the chain (`rings` rings of
// `around` vertices), blending from the root to the child between y = 0.8 and
// 1.2 (weights 0.5 / 0.5 on the joint ring when `rings` is odd); one
// influence per vertex when `rigid`.
inline Character tubeCharacter(int rings, int around, bool rigid) {
  Character c;
  c.skeleton = twoBoneChain();
  Mesh m;
  m.name = "tube";
  for (int r = 0; r < rings; ++r) {
    const float y = 2.0f * r / (rings - 1);
    for (int a = 0; a < around; ++a) {
      const float phi = 2.0f * float(M_PI) * a / around;
      m.positions.insert(m.positions.end(), {0.2f * std::cos(phi), y, 0.2f * std::sin(phi)});
      m.normals.insert(m.normals.end(), {std::cos(phi), 0.0f, std::sin(phi)});
      const float w1 = std::clamp((y - 0.8f) / 0.4f, 0.0f, 1.0f);
      m.skin.joints.insert(m.skin.joints.end(), {0, 1});
      m.skin.weights.insert(m.skin.weights.end(), {1.0f - w1, w1});
    }
  }
  for (int r = 0; r + 1 < rings; ++r)
    for (int a = 0; a < around; ++a) {
      const uint32_t i0 = r * around + a, i1 = r * around + (a + 1) % around;
      const uint32_t i2 = i0 + around, i3 = i1 + around;
      m.triangles.insert(m.triangles.end(), {i0, i2, i1, i1, i2, i3});
    }
  m.skin.influencesPerVertex = 2;
  m.skin.jointBones = {0, 1};
  m.skin.inverseBind = c.skeleton.inverseBindMatrices();
  if (rigid) m.skin.makeRigid();
  c.meshes.push_back(m);
  return c;
}

// The tube's bend by `degrees` about +Z at its joint (0, 1, 0), its inner
// side towards -X.
inline BendFrame tubeBend(float degrees) {
  const double a = glm::radians(double(degrees));
  BendFrame bend;
  bend.jointRest = bend.jointPosed = {0, 1, 0};
  bend.parentRest = bend.parentPosed = bend.childRest = {0, 1, 0};
  bend.childPosed = {-std::sin(a), std::cos(a), 0};
  bend.inward = {-1, 0, 0};
  return bend;
}

// Posing on two threads gives the single-threaded result bit for bit.
inline void expectThreadedEqualsSingleThreaded(const Character& c, const PoseEdits& edits) {
  ThreadPool pool(2);
  PosedCharacter single, threaded;
  single.evaluate(c, -1, 0.0f, &edits, nullptr);
  threaded.evaluate(c, -1, 0.0f, &edits, &pool);
  EXPECT_EQ(single.meshes()[0].positions, threaded.meshes()[0].positions);
  EXPECT_EQ(single.meshes()[0].normals, threaded.meshes()[0].normals);
}

}  // namespace mq
