#include "app/cli/render_garments.h"

#include <cmath>

#include "core/character/posed_character.h"
#include "core/garment/garment_json.h"
#include "core/util/error.h"
#include "core/util/thread_pool.h"

#include "render/cloth_shading.h"
#include "render/scene_view.h"
#include "sim/cloth/cloth_scene_io.h"
#include "sim/garment/dressing.h"
#include "sim/garment/garment_layers.h"
#include "sim/garment/garment_scene.h"

namespace mq::cli {

namespace {

std::vector<float> bodyAt(const Character& character, int clip, float time, const PoseEdits& edits) {
  PosedCharacter posed;
  posed.evaluate(character, clip, time, &edits, &ThreadPool::shared());
  return concatenatedPositions(posed.meshes());
}

}  // namespace

RenderedGarments::RenderedGarments() = default;
RenderedGarments::~RenderedGarments() = default;
RenderedGarments::RenderedGarments(RenderedGarments&&) noexcept = default;

RenderedGarments addSceneGarments(render::SceneView& view, const LoadedScene& scene, int clip, float time,
                                  const std::string& file) {
  RenderedGarments rendered;
  std::vector<Garment> garments;
  cloth::ClothSceneSpec spec;
  try {
    garments = garmentsFromJson(scene.document.garments);
    if (garments.empty()) return rendered;
    spec = cloth::parseClothScene(scene.document.cloth, scene.document.colliders, file, true);
  } catch (const FileError&) {
    throw;
  } catch (const Error& e) {
    throw FileError(file, e.what());
  }
  const Character& character = scene.character;
  const std::vector<float> rest = bodyAt(character, -1, 0.0f, scene.edits);
  const std::vector<uint32_t> triangles = concatenatedTriangles(character);
  const float dt = 1.0f / spec.fps;
  const float start = clip >= 0 ? character.clips[clip].startTime() : 0.0f;
  const std::vector<float> first = bodyAt(character, clip, start, scene.edits);
  const int clipSteps = clip >= 0 ? std::max(0, int(std::lround((time - start) / dt))) : 0;

  // Dressed as every path dresses (sim/garment/dressing.h), then the clip's
  // frames up to `time`, stepped together inner to outer.
  std::vector<std::unique_ptr<cloth::GarmentSimulation>> owned(garments.size());
  std::vector<cloth::GarmentSimulation*> simulations;
  auto pathOf = [](size_t g) { return "garments[" + std::to_string(g) + "]"; };
  for (size_t g = 0; g < garments.size(); ++g) {
    try {
      owned[g] = cloth::makeGarmentSimulation(garments[g], spec, rest, triangles, pathOf(g));
    } catch (const Error& e) {
      throw FileError(file, pathOf(g) + ": " + e.what());
    }
    simulations.push_back(owned[g].get());
  }
  const std::vector<size_t> order = cloth::layerOrder(garments);
  std::vector<int> steps(garments.size(), 0);
  try {
    const std::vector<cloth::DrapeSteps> dressing =
        cloth::dressGarments(simulations, order, rest, first, dt, [](size_t) { return true; });
    for (size_t g = 0; g < garments.size(); ++g)
      steps[g] = dressing[g].total + int(std::ceil(cloth::kDressingSettleSeconds / dt));
  } catch (const Error& e) {
    throw FileError(file, std::string("garments: ") + e.what());
  }
  auto stepAll = [&](const std::vector<float>& body) {
    for (size_t g : order) {
      try {
        simulations[g]->step(dt, &body);
        ++steps[g];
      } catch (const Error& e) {
        throw FileError(file, pathOf(g) + ": " + e.what());
      }
    }
  };
  for (int s = 1; s <= clipSteps; ++s) stepAll(bodyAt(character, clip, start + s * dt, scene.edits));

  for (size_t g = 0; g < garments.size(); ++g) {
    const cloth::GarmentSimulation& simulation = *simulations[g];
    const GarmentMesh mesh = buildGarmentMesh(garments[g]);
    auto actor = std::make_unique<render::ClothActor>();
    actor->setMesh(simulation.positions(), simulation.triangles(), mesh.restUvs);
    actor->setShading(render::clothShadingForFabric(garments[g].fabric));
    view.add(*actor);
    rendered.actors.push_back(std::move(actor));
    rendered.summary += (rendered.summary.empty() ? "" : ", ") + garments[g].name + " (" +
                        std::to_string(simulation.vertexCount()) + " vertices, " + std::to_string(steps[g]) + " steps" +
                        (simulation.welded() ? "" : ", seams not welded") + ")";
  }
  return rendered;
}

}  // namespace mq::cli
