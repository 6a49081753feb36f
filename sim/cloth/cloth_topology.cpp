#include "sim/cloth/cloth_topology.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/util/error.h"

namespace mq::cloth {

namespace {

struct EdgeRecord {
  uint32_t a, b;         // a < b
  uint32_t opposite[2];  // the vertex opposite the edge in each adjacent triangle
  float triangleArea[2];
  int triangles = 0;
};

uint64_t edgeKey(uint32_t a, uint32_t b) { return (uint64_t(std::min(a, b)) << 32) | std::max(a, b); }

void validateMesh(const ClothMesh& mesh) {
  const size_t n = mesh.vertexCount();
  if (n == 0 || mesh.triangles.empty()) throw Error("cloth mesh has no vertices or no triangles");
  if (mesh.positions.size() % 3 != 0 || mesh.triangles.size() % 3 != 0)
    throw Error("cloth mesh arrays are not multiples of 3");
  for (float p : mesh.positions)
    if (!std::isfinite(p)) throw Error("cloth mesh has a non-finite vertex position");
  for (uint32_t t : mesh.triangles)
    if (t >= n) throw Error("cloth mesh triangle index out of range");
  if (!mesh.masses.empty() && mesh.masses.size() != n) throw Error("cloth mesh has a mass count != vertex count");
}

std::vector<EdgeRecord> collectEdges(const ClothMesh& mesh, ClothTopology& topo) {
  std::map<uint64_t, uint32_t> index;  // ordered: deterministic edge order
  std::vector<EdgeRecord> edges;
  topo.vertexArea.assign(mesh.vertexCount(), 0.0f);
  for (size_t t = 0; t < mesh.triangles.size(); t += 3) {
    const uint32_t v[3] = {mesh.triangles[t], mesh.triangles[t + 1], mesh.triangles[t + 2]};
    const float area = 0.5f * glm::length(glm::cross(vec3At(mesh.positions, v[1]) - vec3At(mesh.positions, v[0]),
                                                     vec3At(mesh.positions, v[2]) - vec3At(mesh.positions, v[0])));
    topo.totalArea += area;
    for (int c = 0; c < 3; ++c) {
      topo.vertexArea[v[c]] += area / 3.0f;
      const uint32_t a = v[c], b = v[(c + 1) % 3], opp = v[(c + 2) % 3];
      auto [it, added] = index.emplace(edgeKey(a, b), uint32_t(edges.size()));
      if (added) edges.push_back({std::min(a, b), std::max(a, b), {0, 0}, {0, 0}, 0});
      EdgeRecord& e = edges[it->second];
      if (e.triangles < 2) {
        e.opposite[e.triangles] = opp;
        e.triangleArea[e.triangles] = area;
      }
      ++e.triangles;
    }
  }
  return edges;
}

float distance(const ClothMesh& mesh, uint32_t a, uint32_t b) {
  return glm::length(vec3At(mesh.positions, a) - vec3At(mesh.positions, b));
}

// Nearly straight two-edge paths i-k-j through every vertex k: for each
// neighbour i, the neighbour j making the straightest continuation.
void collectBendLines(const ClothMesh& mesh, const std::vector<EdgeRecord>& edges, ClothTopology& topo) {
  const size_t n = mesh.vertexCount();
  std::vector<std::vector<std::pair<uint32_t, float>>> neighbours(n);  // (vertex, edge area)
  for (const EdgeRecord& e : edges) {
    const float area = e.triangleArea[0] + (e.triangles > 1 ? e.triangleArea[1] : 0.0f);
    neighbours[e.a].push_back({e.b, area});
    neighbours[e.b].push_back({e.a, area});
  }
  const float cosLimit = std::cos(150.0f * 3.14159265f / 180.0f);
  for (uint32_t k = 0; k < n; ++k) {
    const glm::vec3 xk = vec3At(mesh.positions, k);
    for (const auto& [i, areaI] : neighbours[k]) {
      const glm::vec3 d0 = xk - vec3At(mesh.positions, i);
      float bestCos = -cosLimit;  // want the direction of j - k closest to d0
      int best = -1;
      float bestArea = 0.0f;
      for (const auto& [j, areaJ] : neighbours[k]) {
        if (j <= i) continue;  // each line once (i < j)
        const glm::vec3 d1 = vec3At(mesh.positions, j) - xk;
        const float c = glm::dot(d0, d1) / (glm::length(d0) * glm::length(d1) + 1e-30f);
        if (c >= bestCos) {
          bestCos = c;
          best = int(j);
          bestArea = areaJ;
        }
      }
      if (best < 0) continue;
      const uint32_t j = uint32_t(best);
      const float l0 = glm::length(d0), l1 = distance(mesh, k, j);
      const float width = 0.5f * (areaI + bestArea) / (0.5f * (l0 + l1));
      topo.bendLines.push_back({i, k, j, l0, l1, width});
      topo.bend.push_back({i, j, distance(mesh, i, j), 0.5f * (areaI + bestArea)});
    }
  }
}

}  // namespace

ClothTopology buildClothTopology(const ClothMesh& mesh) {
  validateMesh(mesh);
  ClothTopology topo;
  const std::vector<EdgeRecord> edges = collectEdges(mesh, topo);
  for (const EdgeRecord& e : edges) {
    const float area = e.triangleArea[0] + (e.triangles > 1 ? e.triangleArea[1] : 0.0f);
    const float rest = distance(mesh, e.a, e.b);
    if (!(rest > 0.0f)) throw Error("cloth mesh has a zero-length edge");
    topo.structural.push_back({e.a, e.b, rest, area});
    if (e.triangles == 2 && e.opposite[0] != e.opposite[1])
      topo.shear.push_back({e.opposite[0], e.opposite[1], distance(mesh, e.opposite[0], e.opposite[1]), area});
  }
  collectBendLines(mesh, edges, topo);
  return topo;
}

}  // namespace mq::cloth
