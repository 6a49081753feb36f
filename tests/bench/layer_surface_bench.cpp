// Layering's cost per solver step (sim/cloth/collision/cloth_surface_collider.h):
// the default trousers (3 cm edges, as placed around the mannequin) as the
// inner surface, queried from the default T-shirt's vertices (as placed), one
// thread. Counter ns_per_query: CPU time per nearest-contact query;
// ms_per_move: CPU time of one moveTo (normals and the tree's refit).
//
//   BM_LayerSurfaceNearest   nearestContact at the layer contact radius (2 cm)
//   BM_LayerSurfaceMove      moveTo, once per solver step
//
//   mannequin-bench --benchmark_filter=LayerSurface
#include <benchmark/benchmark.h>

#include <ctime>

#include "core/character/default_mannequin.h"
#include "core/garment/parametric_garments.h"
#include "sim/cloth/collision/cloth_surface_collider.h"
#include "tests/bench/query_timing.h"

namespace {

using namespace mq::cloth;

struct LayerScene {
  ClothSurfaceCollider surface;
  std::vector<glm::vec3> target, points;
};

mq::GarmentMesh placedGarment(const std::string& type, const mq::Character& body) {
  mq::Garment garment = mq::makeParametricGarment(type, body);
  garment.targetEdgeLength = 0.03f;
  return mq::buildGarmentMesh(garment);
}

std::vector<glm::vec3> positionsOf(const mq::GarmentMesh& mesh) {
  std::vector<glm::vec3> x(mesh.vertexCount());
  for (size_t i = 0; i < x.size(); ++i)
    x[i] = {mesh.positions[3 * i], mesh.positions[3 * i + 1], mesh.positions[3 * i + 2]};
  return x;
}

LayerScene& layerScene() {
  static LayerScene scene = [] {
    LayerScene s;
    const mq::Character mannequin = mq::makeDefaultMannequin();
    const mq::GarmentMesh trousers = placedGarment("trousers", mannequin);
    const std::vector<glm::vec3> x = positionsOf(trousers);
    s.surface.setMesh(x, trousers.triangles);
    s.target = x;
    for (glm::vec3& p : s.target) p.y += 0.01f;  // a 1 cm move in the step
    s.surface.setTarget(s.target, 1.0f / 30.0f);
    s.points = positionsOf(placedGarment("tshirt", mannequin));
    return s;
  }();
  return scene;
}

void BM_LayerSurfaceNearest(benchmark::State& state) {
  LayerScene& s = layerScene();
  s.surface.moveTo(0.5f);
  mq::bench::timeQueries(state, s.points.size(), [&](size_t i) {
    SurfaceContact contact;
    return s.surface.nearestContact(s.points[i], 0.02f, contact);
  });
}
BENCHMARK(BM_LayerSurfaceNearest)->Unit(benchmark::kMicrosecond);

void BM_LayerSurfaceMove(benchmark::State& state) {
  LayerScene& s = layerScene();
  double cpuSeconds = 0.0;
  float fraction = 0.0f;
  for (auto _ : state) {
    const std::clock_t cpuStart = std::clock();
    s.surface.moveTo(fraction);
    cpuSeconds += double(std::clock() - cpuStart) / CLOCKS_PER_SEC;
    fraction = fraction > 0.9f ? 0.0f : fraction + 0.1f;
  }
  state.counters["ms_per_move"] = 1e3 * cpuSeconds / double(std::max<int64_t>(1, state.iterations()));
  state.counters["vertices"] = double(s.surface.vertexCount());
}
BENCHMARK(BM_LayerSurfaceMove)->Unit(benchmark::kMicrosecond);

}  // namespace
