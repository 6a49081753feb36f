#include "core/mesh/marching_cubes.h"

#include <algorithm>
#include <array>
#include <stdexcept>

namespace mq {
namespace {

// Cube corner c sits at offset (c & 1, (c >> 1) & 1, (c >> 2) & 1).
glm::ivec3 cornerOffset(int c) { return {c & 1, (c >> 1) & 1, (c >> 2) & 1}; }

struct CubeEdge {
  int corner0, corner1, axis;  // corner1 = corner0 + unit step along axis
};

struct CubeFace {
  std::array<int, 4> ccwCorners;        // counter-clockwise seen from outside the cube
  std::array<int, 4> ccwEdges;          // edge m joins ccwCorners[m] and ccwCorners[m + 1]
  std::array<int, 4> canonicalCorners;  // square order in the face's (u, v) axes, same for both cubes
};

struct CubeTopology {
  std::array<CubeEdge, 12> edges;
  std::array<CubeFace, 6> faces;

  // Whether two cube edges lie on a common face: a diagonal between their
  // vertices would lie in that face, where the neighbouring cube could
  // create it too.
  std::array<std::array<bool, 12>, 12> shareFace{};

  int edgeBetween(int a, int b) const {
    for (int e = 0; e < 12; ++e)
      if ((edges[e].corner0 == a && edges[e].corner1 == b) || (edges[e].corner0 == b && edges[e].corner1 == a))
        return e;
    throw std::logic_error("corners are not adjacent");
  }

  CubeTopology() {
    int e = 0;
    for (int axis = 0; axis < 3; ++axis)
      for (int c = 0; c < 8; ++c)
        if (!(c & (1 << axis))) edges[e++] = {c, c | (1 << axis), axis};
    int f = 0;
    for (int axis = 0; axis < 3; ++axis) {
      const int u = axis == 0 ? 1 : 0, v = axis == 2 ? 1 : 2;
      for (int side = 0; side < 2; ++side) {
        CubeFace& face = faces[f++];
        const int base = side << axis;
        face.canonicalCorners = {base, base | (1 << u), base | (1 << u) | (1 << v), base | (1 << v)};
        // The (u, v) square turns about +axis when e_u x e_v = +e_axis; flip it
        // where that disagrees with the face's outward normal.
        const glm::vec3 turn = glm::cross(glm::vec3(cornerOffset(1 << u)), glm::vec3(cornerOffset(1 << v)));
        const float outward = side ? 1.0f : -1.0f;
        face.ccwCorners = face.canonicalCorners;
        if (turn[axis] * outward < 0.0f) std::reverse(face.ccwCorners.begin(), face.ccwCorners.end());
        for (int m = 0; m < 4; ++m) face.ccwEdges[m] = edgeBetween(face.ccwCorners[m], face.ccwCorners[(m + 1) % 4]);
        for (int a : face.ccwEdges)
          for (int b : face.ccwEdges) shareFace[a][b] = true;
      }
    }
  }
};

const CubeTopology& topology() {
  static const CubeTopology t;
  return t;
}

// On an ambiguous face (inside corners on one diagonal), whether the inside
// corners connect through the face: the bilinear interpolant's saddle value
// is inside. Values are relative to iso and in canonical order, so both cubes
// sharing the face compute the same bits.
bool insideConnectsAcrossFace(const std::array<float, 4>& a) {
  const float denominator = a[0] + a[2] - a[1] - a[3];
  const float saddleTimesDenominator = a[0] * a[2] - a[1] * a[3];
  // saddle < 0  <=>  numerator and denominator have opposite signs
  return (saddleTimesDenominator < 0.0f) != (denominator < 0.0f);
}

// Directed contour segments (cube edge -> cube edge) on one face, oriented so
// that the loops they form run counter-clockwise around the outward normal of
// the surface (seen from outside the solid).
int faceSegments(const CubeFace& face, const float* relative, std::array<std::pair<int, int>, 2>& out) {
  std::array<bool, 4> inside{};
  int insideCount = 0;
  for (int m = 0; m < 4; ++m) insideCount += inside[m] = relative[face.ccwCorners[m]] < 0.0f;
  if (insideCount == 0 || insideCount == 4) return 0;
  const bool ambiguous = insideCount == 2 && inside[0] == inside[2];
  int count = 0;
  if (ambiguous) {
    std::array<float, 4> canonical;
    for (int m = 0; m < 4; ++m) canonical[m] = relative[face.canonicalCorners[m]];
    if (insideConnectsAcrossFace(canonical)) {
      // Each outside corner is cut off on its own.
      for (int m = 0; m < 4; ++m)
        if (!inside[m]) out[count++] = {face.ccwEdges[m], face.ccwEdges[(m + 3) % 4]};
      return count;
    }
  }
  // Each run of consecutive inside corners is cut off by one segment from the
  // edge entering the run to the edge leaving it.
  for (int m = 0; m < 4; ++m) {
    if (!inside[m] || inside[(m + 3) % 4]) continue;
    int last = m;
    while (inside[(last + 1) % 4]) last = (last + 1) % 4;
    out[count++] = {face.ccwEdges[(m + 3) % 4], face.ccwEdges[last]};
  }
  return count;
}

class Extractor {
 public:
  Extractor(const ScalarGrid& grid, float iso) : grid_(grid), iso_(iso) {
    edgeVertex_.assign(3 * grid.values.size(), -1);
  }

  IsoSurface run() {
    const glm::ivec3 d = grid_.dims;
    for (int k = 0; k + 1 < d.z; ++k)
      for (int j = 0; j + 1 < d.y; ++j)
        for (int i = 0; i + 1 < d.x; ++i) polygoniseCell({i, j, k});
    return std::move(surface_);
  }

 private:
  void polygoniseCell(const glm::ivec3& cell) {
    std::array<float, 8> relative;
    int insideCount = 0;
    for (int c = 0; c < 8; ++c) {
      const glm::ivec3 p = cell + cornerOffset(c);
      relative[c] = grid_.at(p.x, p.y, p.z) - iso_;
      insideCount += relative[c] < 0.0f;
    }
    if (insideCount == 0 || insideCount == 8) return;

    const CubeTopology& topo = topology();
    std::array<int, 12> next;
    next.fill(-1);
    for (const CubeFace& face : topo.faces) {
      std::array<std::pair<int, int>, 2> segments;
      const int n = faceSegments(face, relative.data(), segments);
      for (int s = 0; s < n; ++s) {
        if (next[segments[s].first] != -1) throw std::logic_error("marching cubes: edge leaves twice");
        next[segments[s].first] = segments[s].second;
      }
    }
    std::array<bool, 12> used{};
    for (int start = 0; start < 12; ++start) {
      if (next[start] == -1 || used[start]) continue;
      loop_.clear();
      for (int e = start; !used[e]; e = next[e]) {
        if (next[e] == -1) throw std::logic_error("marching cubes: open contour");
        used[e] = true;
        loop_.push_back({vertexOnEdge(cell, topo.edges[e], relative), e});
      }
      triangulateLoop();
    }
  }

  uint32_t vertexOnEdge(const glm::ivec3& cell, const CubeEdge& edge, const std::array<float, 8>& relative) {
    const glm::ivec3 p = cell + cornerOffset(edge.corner0);
    const size_t id = 3 * grid_.index(p.x, p.y, p.z) + edge.axis;
    if (edgeVertex_[id] >= 0) return static_cast<uint32_t>(edgeVertex_[id]);
    const float a = relative[edge.corner0], b = relative[edge.corner1];
    // Kept off the corners so no two vertices coincide and no triangle collapses.
    const float t = std::clamp(a / (a - b), 0.02f, 0.98f);
    glm::vec3 position = grid_.point(p.x, p.y, p.z);
    position[edge.axis] += t * grid_.cellSize;
    const uint32_t v = static_cast<uint32_t>(surface_.positions.size() / 3);
    surface_.positions.insert(surface_.positions.end(), {position.x, position.y, position.z});
    edgeVertex_[id] = static_cast<int32_t>(v);
    return v;
  }

  glm::vec3 position(uint32_t v) const {
    return {surface_.positions[3 * v], surface_.positions[3 * v + 1], surface_.positions[3 * v + 2]};
  }

  // Ear clipping that always cuts the ear with the shortest new diagonal,
  // keeping the loop's orientation. Diagonals between vertices on a common
  // cube face are not allowed, so every diagonal belongs to this cube alone
  // and the mesh stays manifold; a loop with no allowed ear is fanned around
  // a new vertex at its centroid instead.
  void triangulateLoop() {
    const CubeTopology& topo = topology();
    while (loop_.size() > 3) {
      const size_t n = loop_.size();
      size_t best = n;
      float bestLength = 1e30f;
      for (size_t m = 0; m < n; ++m) {
        const LoopVertex& prev = loop_[(m + n - 1) % n];
        const LoopVertex& next = loop_[(m + 1) % n];
        if (topo.shareFace[prev.cubeEdge][next.cubeEdge]) continue;
        const float length = glm::distance(position(prev.vertex), position(next.vertex));
        if (length < bestLength) bestLength = length, best = m;
      }
      if (best == n) return fanAroundCentroid();
      emit(loop_[(best + n - 1) % n].vertex, loop_[best].vertex, loop_[(best + 1) % n].vertex);
      loop_.erase(loop_.begin() + best);
    }
    emit(loop_[0].vertex, loop_[1].vertex, loop_[2].vertex);
  }

  void fanAroundCentroid() {
    glm::vec3 centroid(0.0f);
    for (const LoopVertex& l : loop_) centroid += position(l.vertex);
    centroid /= float(loop_.size());
    const uint32_t center = static_cast<uint32_t>(surface_.positions.size() / 3);
    surface_.positions.insert(surface_.positions.end(), {centroid.x, centroid.y, centroid.z});
    for (size_t m = 0; m < loop_.size(); ++m) emit(center, loop_[m].vertex, loop_[(m + 1) % loop_.size()].vertex);
  }

  void emit(uint32_t a, uint32_t b, uint32_t c) { surface_.triangles.insert(surface_.triangles.end(), {a, b, c}); }

  const ScalarGrid& grid_;
  float iso_;
  std::vector<int32_t> edgeVertex_;  // per grid point and axis: vertex on that edge, or -1
  struct LoopVertex {
    uint32_t vertex;
    int cubeEdge;
  };
  std::vector<LoopVertex> loop_;
  IsoSurface surface_;
};

}  // namespace

IsoSurface extractIsoSurface(const ScalarGrid& grid, float iso) {
  if (grid.values.size() != size_t(grid.dims.x) * grid.dims.y * grid.dims.z)
    throw std::invalid_argument("extractIsoSurface: grid size does not match its dimensions");
  return Extractor(grid, iso).run();
}

}  // namespace mq
