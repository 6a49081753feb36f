#include "app/cli/scene_cloth.h"

#include "core/util/thread_pool.h"

namespace mq::cli {

void PosedBody::pose(float time, std::vector<float>& positions, std::vector<uint32_t>* triangles, bool rest) {
  posed_.evaluate(scene_.character, rest ? -1 : scene_.clipIndex, rest ? 0.0f : time, rest ? nullptr : &scene_.edits,
                  &ThreadPool::shared());
  positions = concatenatedPositions(posed_.meshes());
  if (triangles) *triangles = concatenatedTriangles(scene_.character);
}

std::unique_ptr<cloth::ClothSimulator> makeSheet(const cloth::ClothSceneSpec& spec, const std::vector<float>& body,
                                                 const std::vector<uint32_t>& bodyTriangles) {
  if (!spec.hasSheet) return nullptr;
  std::vector<uint32_t> pinned;
  auto sim = std::make_unique<cloth::ClothSimulator>(cloth::buildClothMesh(spec, pinned), spec.fabric, spec.settings);
  for (const auto& c : spec.colliders) sim->addCollider(c);
  for (uint32_t v : pinned) sim->pinVertex(v);
  if (!bodyTriangles.empty()) sim->setBody(body, bodyTriangles);
  return sim;
}

}  // namespace mq::cli
