#include "sim/garment/garment_sewing.h"

#include <algorithm>
#include <map>

namespace mq::cloth {
namespace {

// Maps spring ends through the weld; merges springs that now join the same
// two vertices (areas add up, rest lengths average).
std::vector<SpringTopology> remapSprings(const std::vector<SpringTopology>& springs, const SeamWeld& weld) {
  std::vector<SpringTopology> out;
  std::map<std::pair<uint32_t, uint32_t>, size_t> existing;
  std::vector<int> merged;
  for (const SpringTopology& s : springs) {
    uint32_t a = weld.newIndex[s.a], b = weld.newIndex[s.b];
    if (a == b) continue;
    auto key = std::make_pair(std::min(a, b), std::max(a, b));
    auto [it, inserted] = existing.try_emplace(key, out.size());
    if (inserted) {
      out.push_back({a, b, s.restLength, s.area});
      merged.push_back(1);
    } else {
      SpringTopology& kept = out[it->second];
      int n = ++merged[it->second];
      kept.restLength += (s.restLength - kept.restLength) / float(n);
      kept.area += s.area;
    }
  }
  return out;
}

}  // namespace

ClothMesh clothMeshFromGarment(const GarmentMesh& garment) {
  ClothMesh mesh;
  mesh.positions = garment.positions;
  mesh.triangles = garment.triangles;
  mesh.seams = garment.seamPairs;
  return mesh;
}

float maxSeamGap(const std::vector<glm::vec3>& x, const std::vector<std::pair<uint32_t, uint32_t>>& seams) {
  float gap = 0.0f;
  for (auto [a, b] : seams) gap = std::max(gap, glm::length(x[a] - x[b]));
  return gap;
}

WeldedCloth weldClothSeams(const ClothMesh& mesh, const ClothTopology& topology) {
  WeldedCloth out;
  out.weld = computeSeamWeld(mesh.vertexCount(), mesh.seams);
  out.mesh.positions = weldAverage(out.weld, mesh.positions, 3);
  out.mesh.triangles = weldTriangles(out.weld, mesh.triangles);
  if (!mesh.masses.empty()) out.mesh.masses = weldSum(out.weld, mesh.masses);
  out.topology.structural = remapSprings(topology.structural, out.weld);
  out.topology.shear = remapSprings(topology.shear, out.weld);
  // Bend springs and bend lines stay paired by index: keep both or neither.
  for (size_t n = 0; n < topology.bendLines.size(); ++n) {
    BendLine line = topology.bendLines[n];
    line.i = out.weld.newIndex[line.i], line.k = out.weld.newIndex[line.k], line.j = out.weld.newIndex[line.j];
    if (line.i == line.k || line.k == line.j || line.i == line.j) continue;
    SpringTopology spring = topology.bend[n];
    spring.a = out.weld.newIndex[spring.a], spring.b = out.weld.newIndex[spring.b];
    out.topology.bendLines.push_back(line);
    out.topology.bend.push_back(spring);
  }
  out.topology.vertexArea = weldSum(out.weld, topology.vertexArea);
  out.topology.totalArea = topology.totalArea;
  return out;
}

std::unique_ptr<ClothSimulator> continueWelded(const ClothSimulator& sewing, const WeldedCloth& welded,
                                               const Fabric& fabric, const ClothSettings* settings) {
  const ClothState& old = sewing.state();
  std::vector<float> x(3 * old.size()), v(3 * old.size());
  for (size_t i = 0; i < old.size(); ++i)
    for (int c = 0; c < 3; ++c) x[3 * i + c] = old.x[i][c], v[3 * i + c] = old.v[i][c];
  ClothMesh mesh = welded.mesh;
  mesh.positions = weldAverage(welded.weld, x, 3);
  mesh.masses = weldSum(welded.weld, old.mass);
  auto sim = std::make_unique<ClothSimulator>(mesh, welded.topology, fabric, settings ? *settings : sewing.settings());
  std::vector<float> velocities = weldAverage(welded.weld, v, 3);
  ClothState& state = sim->mutableState();
  for (size_t i = 0; i < state.size(); ++i) state.v[i] = vec3At(velocities, i);
  for (const PrimitiveCollider& c : sewing.colliders()) sim->addCollider(c);
  return sim;
}

}  // namespace mq::cloth
