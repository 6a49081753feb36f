#include "app/cli/scene_take.h"

#include <memory>

#include "app/cli/scene_cloth.h"
#include "app/cli/scene_hair.h"
#include "app/cli/simulate_garments.h"
#include "core/garment/fabric_color.h"
#include "core/util/error.h"
#include "core/util/memory_budget.h"

namespace mq::cli {
namespace {

bool hasGarments(const LoadedScene& scene) {
  return scene.document.garments.is_array() && !scene.document.garments.empty();
}

std::vector<BakedSurface> recordCloth(const LoadedScene& scene, const std::string& path, const TakeRequest& request) {
  const bool garmentsToo = hasGarments(scene);
  const cloth::ClothSceneSpec spec =
      cloth::parseClothScene(scene.document.cloth, scene.document.colliders, path, garmentsToo);
  const float dt = 1.0f / request.fps;
  PosedBody body(scene);
  std::vector<float> bodyPositions;
  std::vector<uint32_t> bodyTriangles;
  if (!body.empty()) body.pose(scene.document.time, bodyPositions, &bodyTriangles);
  std::unique_ptr<cloth::ClothSimulator> sheet = makeSheet(spec, bodyPositions, bodyTriangles);
  std::unique_ptr<SimulatedGarments> garments;
  if (garmentsToo) {
    // Sewn on the rest pose, then dressed to the scene's pose, as simulate does.
    std::vector<float> restBody;
    if (!body.empty()) body.pose(0.0f, restBody, nullptr, true);
    garments = std::make_unique<SimulatedGarments>(scene.document.garments, spec, restBody, bodyTriangles, path);
    garments->dress(restBody, bodyPositions, dt);
  }
  // Kept per frame: positions, then the file's positions and normals.
  ClothNow now;
  if (sheet) now.add(*sheet, sheet->positions().size());
  if (garments) garments->addTo(now);
  checkMemoryBudget("the cloth's frames (" + std::to_string(now.vertices) + " vertices x " +
                        std::to_string(request.frames) + " frames)",
                    36.0 * double(now.vertices) * request.frames);
  BakedSurface sheetSurface;
  if (sheet) {
    sheetSurface.name = "cloth";
    sheetSurface.triangles = sheet->triangles();
    sheetSurface.color = glm::vec4(fabricColor(spec.fabricPreset), 1.0f);
  }
  const bool moving = !body.empty() && spec.animateBody;
  for (int f = 0; f < request.frames; ++f) {
    if (moving) body.pose(takeFrameTime(scene, f, request.fps), bodyPositions, nullptr);
    if (sheet) {
      if (moving) sheet->updateBody(bodyPositions);
      sheet->step(dt);
      sheetSurface.frames.push_back(sheet->flatPositions());
    }
    if (garments) {
      garments->step(dt, moving ? &bodyPositions : nullptr);
      garments->recordFrame(request.fps);
    }
  }
  std::vector<BakedSurface> surfaces = garments ? garments->bakedSurfaces() : std::vector<BakedSurface>{};
  if (sheet) surfaces.push_back(std::move(sheetSurface));
  return surfaces;
}

BakedSurface recordHair(const LoadedScene& scene, const TakeRequest& request) {
  constexpr float kSettleSeconds = 0.5f;  // as simulate settles
  SceneHair hair(scene, sceneHairSection(scene));
  const size_t all = hair.groom().strands().strandCount();
  const size_t strands = request.hairStrands < 0    ? hair.groom().guideCount()
                         : request.hairStrands == 0 ? all
                                                    : std::min(all, size_t(request.hairStrands));
  const size_t floats = 3 * strands * size_t(hair.groom().strands().pointsPerStrand);
  checkMemoryBudget(
      "the hair's frames (" + std::to_string(strands) + " strands x " + std::to_string(request.frames) + " frames)",
      4.0 * double(floats) * request.frames);
  BakedSurface s =
      strandLines(strands, hair.groom().strands().pointsPerStrand, hair.style().rootColor, hair.style().tipColor);
  const float dt = 1.0f / request.fps;
  hair.settle(scene.document.time, kSettleSeconds, request.fps);
  for (int f = 0; f < request.frames; ++f) {
    hair.step(takeFrameTime(scene, f, request.fps), dt);
    const std::vector<float>& points = hair.updateAllStrands();
    s.frames.emplace_back(points.begin(), points.begin() + long(floats));
  }
  return s;
}

}  // namespace

std::vector<BakedSurface> recordSceneTake(const LoadedScene& scene, const std::string& path,
                                          const TakeRequest& request) {
  std::vector<BakedSurface> surfaces;
  if (request.cloth) {
    if (scene.document.cloth.is_null() && !hasGarments(scene))
      throw FileError(path, "has no garments and no cloth to export (--with garments)");
    surfaces = recordCloth(scene, path, request);
  }
  if (request.hair) {
    if (!sceneHasHair(scene)) throw FileError(path, "has no hair section to export (--with hair)");
    surfaces.push_back(recordHair(scene, request));
  }
  return surfaces;
}

}  // namespace mq::cli
