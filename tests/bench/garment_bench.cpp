// Garment model: meshing a panel with CGAL's mesher and building a whole
// parametric garment (measure the body, draw, mesh, pair seams, place).
#include <benchmark/benchmark.h>

#include "core/character/default_mannequin.h"
#include "core/garment/panel_mesher.h"
#include "core/garment/parametric_garments.h"

namespace {

mq::Panel rectangle(float w, float h) {
  mq::Panel p;
  p.name = "rect";
  p.addLine("bottom", {0, 0});
  p.addLine("right", {w, 0});
  p.addLine("top", {w, h});
  p.addLine("left", {0, h});
  return p;
}

// A 0.5 m x 0.7 m panel (a T-shirt front) at a target edge length in mm.
void BM_MeshPanel(benchmark::State& state) {
  const mq::Panel panel = rectangle(0.5f, 0.7f);
  const float target = float(state.range(0)) * 1e-3f;
  size_t triangles = 0;
  for (auto _ : state) {
    mq::PanelMesh mesh = mq::meshPanel(panel, {target, {}});
    triangles = mesh.triangleCount();
    benchmark::DoNotOptimize(mesh.vertices.data());
  }
  state.counters["triangles"] = double(triangles);
}
BENCHMARK(BM_MeshPanel)->Arg(20)->Arg(10)->Unit(benchmark::kMillisecond);

// makeParametricGarment + buildGarmentMesh on the default mannequin.
void BM_BuildGarment(benchmark::State& state, const char* type) {
  static const mq::Character body = mq::makeDefaultMannequin();
  const float target = float(state.range(0)) * 1e-3f;
  size_t vertices = 0;
  for (auto _ : state) {
    mq::Garment garment = mq::makeParametricGarment(type, body);
    garment.targetEdgeLength = target;
    mq::GarmentMesh mesh = mq::buildGarmentMesh(garment);
    vertices = mesh.vertexCount();
    benchmark::DoNotOptimize(mesh.positions.data());
  }
  state.counters["vertices"] = double(vertices);
}
BENCHMARK_CAPTURE(BM_BuildGarment, tshirt, "tshirt")->Arg(20)->Arg(10)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_BuildGarment, skirt, "skirt")->Arg(20)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_BuildGarment, trousers, "trousers")->Arg(20)->Unit(benchmark::kMillisecond);

}  // namespace
