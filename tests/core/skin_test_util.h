#pragma once
// Small characters with closed-form skinning behaviour, shared by the
// skinning tests: a two-bone chain along +Y and a tube skinned to it.

#include <algorithm>
#include <cmath>

#include "core/character/character.h"

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

}  // namespace mq
