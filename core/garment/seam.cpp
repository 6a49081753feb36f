#include "core/garment/seam.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace mq {
namespace {

// One side of a seam, walked in A's direction with normalised arc length t.
class SeamSide {
 public:
  SeamSide(PanelMesh& mesh, int edge, bool reversed) : mesh_(mesh), edge_(edge), reversed_(reversed) {}

  size_t size() const { return mesh_.edgeVertices[edge_].size(); }
  float length() const { return mesh_.edgeArcLengths[edge_].back(); }
  uint32_t vertex(size_t i) const { return mesh_.edgeVertices[edge_][stored(i)]; }
  float t(size_t i) const {
    float s = mesh_.edgeArcLengths[edge_][stored(i)] / length();
    return reversed_ ? 1.0f - s : s;
  }
  // Inserts a boundary vertex at normalised position t (strictly between the
  // vertices at walk positions i - 1 and i) and returns it; it takes index i.
  uint32_t insertBefore(size_t i, float tWalk) {
    float s = (reversed_ ? 1.0f - tWalk : tWalk) * length();
    size_t k = reversed_ ? stored(i) : stored(i) - 1;  // stored segment (k, k + 1)
    return mesh_.splitBoundary(edge_, k, s);
  }

 private:
  size_t stored(size_t i) const { return reversed_ ? size() - 1 - i : i; }
  PanelMesh& mesh_;
  int edge_;
  bool reversed_;
};

}  // namespace

std::vector<VertexPair> pairSeamVertices(PanelMesh& meshA, int edgeA, PanelMesh& meshB, int edgeB, bool reversed,
                                         float matchDistance) {
  SeamSide a(meshA, edgeA, false), b(meshB, edgeB, reversed);
  float tolerance = matchDistance / std::max(a.length(), b.length());
  std::vector<VertexPair> pairs;
  size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    float ta = a.t(i), tb = b.t(j);
    bool aEnd = i + 1 == a.size(), bEnd = j + 1 == b.size();  // end corners pair only with each other
    if (aEnd != bEnd) {
      if (aEnd)
        pairs.push_back({a.insertBefore(i++, tb), b.vertex(j++)});
      else
        pairs.push_back({a.vertex(i++), b.insertBefore(j++, ta)});
    } else if (aEnd || std::abs(ta - tb) <= tolerance) {
      pairs.push_back({a.vertex(i++), b.vertex(j++)});
    } else if (ta < tb) {
      pairs.push_back({a.vertex(i++), b.insertBefore(j++, ta)});
    } else {
      pairs.push_back({a.insertBefore(i++, tb), b.vertex(j++)});
    }
  }
  assert(i == a.size() && j == b.size());
  return pairs;
}

}  // namespace mq
