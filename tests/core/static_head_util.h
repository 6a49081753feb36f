#pragma once
// The MakeHuman head scan of ../shared/assets (an OBJ in decimetres) and an
// inside test for it that does not share code with the hair's own.

#include <string>

#include <glm/glm.hpp>

#include "core/io/character_import.h"
#include "core/mesh/triangle_ray_caster.h"

namespace mq::test {

inline Character headScan() {
  Character head =
      importCharacter(std::string(MANNEQUIN_SHARED_DIR) + "/assets/heads/makehuman_hm08_head/makehuman_head.obj");
  head.scaleUniformly(0.1f);  // decimetres
  return head;
}

// A mesh that is not closed (the scan is open at the neck) holds a point when
// rays up, left and right all cross it an odd number of times.
class OpenMeshInside {
 public:
  explicit OpenMeshInside(const Mesh& mesh) : caster_(mesh.positions, mesh.triangles) {}
  bool contains(const glm::vec3& p) const {
    for (const glm::vec3& d : {glm::vec3(0, 1, 0), glm::vec3(1, 0, 0), glm::vec3(-1, 0, 0)})
      if (crossings(p, d) % 2 == 0) return false;
    return true;
  }

 private:
  int crossings(const glm::vec3& p, const glm::vec3& d) const {
    int n = 0;
    for (float t = caster_.firstHit(p, d, 0.0f); t >= 0.0f && n < 64; t = caster_.firstHit(p, d, t + 1e-5f)) ++n;
    return n;
  }
  TriangleRayCaster caster_;
};

}  // namespace mq::test
