#include "core/character/default_mannequin.h"

#include <algorithm>
#include <memory>

#include "core/animation/mannequin_clips.h"
#include "core/character/implicit_body.h"
#include "core/character/mannequin_body.h"
#include "core/mesh/marching_cubes.h"
#include "core/skinning/potential_weights.h"
#include "core/util/thread_pool.h"

namespace mq {
namespace {

// ---- Mesh and tags ---------------------------------------------------------

constexpr float kCellSize = 0.009f;

Mesh polygonise(const ImplicitBody& body) {
  ThreadPool& pool = ThreadPool::shared();
  const ScalarGrid grid = body.sample(kCellSize, &pool);
  IsoSurface surface = extractIsoSurface(grid, 0.0f);
  Mesh mesh;
  mesh.name = "mannequin";
  mesh.positions = std::move(surface.positions);
  mesh.triangles = std::move(surface.triangles);
  mesh.normals.resize(mesh.positions.size());
  pool.parallelFor(0, mesh.vertexCount(), 512, [&](size_t begin, size_t end) {
    for (size_t v = begin; v < end; ++v) {
      const glm::vec3 n = body.normal(mesh.position(v), 0.25f * kCellSize);
      for (int d = 0; d < 3; ++d) mesh.normals[3 * v + d] = n[d];
    }
  });
  mesh.baseColor = {0.82f, 0.7f, 0.56f};
  return mesh;
}

// The hair region: the skull above a line from the forehead over the ears
// down to the nape.
void tagScalp(Mesh& mesh, const Skeleton& skeleton) {
  const int headBone = skeleton.findBone("head");
  const glm::vec3 skull(0.0f, 1.655f, -0.008f);
  mesh.vertexTags.assign(mesh.vertexCount(), TagNone);
  const SkinBinding& skin = mesh.skin;
  const int k = skin.influencesPerVertex;
  for (size_t v = 0; v < mesh.vertexCount(); ++v) {
    float headWeight = 0.0f;
    for (int i = 0; i < k; ++i)
      if (skin.jointBones[skin.joints[v * k + i]] == headBone) headWeight += skin.weights[v * k + i];
    const glm::vec3 r = mesh.position(v) - skull;
    const float frontness = std::clamp((r.z + 0.06f) / 0.11f, 0.0f, 1.0f);
    const float hairline = -0.05f + 0.09f * frontness;
    if (headWeight > 0.5f && r.y > hairline) mesh.vertexTags[v] = TagScalp;
  }
}

}  // namespace

Character makeDefaultMannequin() {
  Character character;
  character.name = "Mannequin";
  character.sourcePath = "default";
  character.skeleton = makeMannequinSkeleton();
  auto body = std::make_shared<const ImplicitBody>(makeMannequinBody(character.skeleton));
  Mesh mesh = polygonise(*body);
  bindPotentialWeights(mesh, *body, character.skeleton);
  tagScalp(mesh, character.skeleton);
  mesh.implicitBody = body;
  character.meshes.push_back(std::move(mesh));
  character.clips.push_back(makeMannequinWalk(character.skeleton));
  character.clips.push_back(makeMannequinArmRaise(character.skeleton));
  character.clips.push_back(makeMannequinHeadTurn(character.skeleton));
  return character;
}

}  // namespace mq
