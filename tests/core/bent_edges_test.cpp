// The share of bent interior edges: flat, folded, welded seams, borders.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "core/mesh/bent_edges.h"

namespace mq {
namespace {

// An n x n grid of unit squares in the xy plane, two triangles each,
// counter-clockwise seen from +z; the columns from `foldColumn` on are turned
// by `foldDegrees` about the line x = foldColumn.
struct Grid {
  std::vector<float> positions;
  std::vector<uint32_t> triangles;
};

Grid grid(int n, int foldColumn, float foldDegrees) {
  Grid g;
  const float angle = foldDegrees * float(M_PI) / 180.0f;
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x) {
      const float along = float(std::max(0, x - foldColumn));
      const float px = x <= foldColumn ? float(x) : float(foldColumn) + along * std::cos(angle);
      const float pz = x <= foldColumn ? 0.0f : along * std::sin(angle);
      g.positions.insert(g.positions.end(), {px, float(y), pz});
    }
  auto id = [n](int x, int y) { return uint32_t(y * (n + 1) + x); };
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      g.triangles.insert(g.triangles.end(), {id(x, y), id(x + 1, y), id(x + 1, y + 1)});
      g.triangles.insert(g.triangles.end(), {id(x, y), id(x + 1, y + 1), id(x, y + 1)});
    }
  return g;
}

// A 4 x 4 grid has 3 * 16 + 8 = 56 edges, 16 of them on the border: 40 interior.
TEST(BentEdges, AFlatSheetHasNone) {
  const Grid g = grid(4, 2, 0.0f);
  const BentEdges bent = bentEdges(g.positions, g.triangles, 15.0f);
  EXPECT_EQ(bent.interiorEdges, 40);
  EXPECT_EQ(bent.bent, 0);
  EXPECT_EQ(bent.share(), 0.0f);
}

TEST(BentEdges, AFoldBendsTheEdgesAlongIt) {
  // The four edges on the line x = 2 separate triangles of the two halves.
  const Grid folded = grid(4, 2, 30.0f);
  BentEdges bent = bentEdges(folded.positions, folded.triangles, 15.0f);
  EXPECT_EQ(bent.interiorEdges, 40);
  EXPECT_EQ(bent.bent, 4);
  EXPECT_FLOAT_EQ(bent.share(), 0.1f);
  // Under the angle, and over it.
  EXPECT_EQ(bentEdges(folded.positions, folded.triangles, 35.0f).bent, 0);
  EXPECT_EQ(bentEdges(grid(4, 2, 10.0f).positions, folded.triangles, 15.0f).bent, 0);
}

TEST(BentEdges, AWeldedSeamIsInterior) {
  // The same fold, with the columns right of the fold given their own
  // vertices at bit-equal positions (two panels sewn along x = 2).
  Grid g = grid(4, 2, 90.0f);
  const uint32_t first = uint32_t(g.positions.size() / 3);
  for (int y = 0; y <= 4; ++y) {
    const uint32_t v = uint32_t(y * 5 + 2);
    g.positions.insert(g.positions.end(), {g.positions[3 * v], g.positions[3 * v + 1], g.positions[3 * v + 2]});
  }
  for (size_t t = 0; t < g.triangles.size() / 3; ++t) {
    uint32_t* tri = &g.triangles[3 * t];
    const bool rightHalf = (tri[0] % 5) >= 2 && (tri[1] % 5) >= 2 && (tri[2] % 5) >= 2;
    if (rightHalf)
      for (int k = 0; k < 3; ++k)
        if (tri[k] % 5 == 2) tri[k] = first + tri[k] / 5;
  }
  const BentEdges bent = bentEdges(g.positions, g.triangles, 15.0f);
  EXPECT_EQ(bent.interiorEdges, 40);
  EXPECT_EQ(bent.bent, 4);
  // Moved apart by a hair, the seam is two borders.
  g.positions[3 * first] += 1e-3f;
  EXPECT_EQ(bentEdges(g.positions, g.triangles, 15.0f).interiorEdges, 39);
}

TEST(BentEdges, DegenerateAndNonManifoldEdgesAreLeftOut) {
  // Three triangles on one edge: not interior.
  const std::vector<float> positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1};
  const std::vector<uint32_t> fan = {0, 1, 2, 1, 0, 3, 0, 1, 4};
  EXPECT_EQ(bentEdges(positions, fan, 15.0f).interiorEdges, 0);
  // A zero-area triangle beside a good one.
  const std::vector<float> flat = {0, 0, 0, 1, 0, 0, 0, 1, 0, 2, 0, 0};
  EXPECT_EQ(bentEdges(flat, {0, 1, 2, 1, 0, 3}, 15.0f).interiorEdges, 0);
}

}  // namespace
}  // namespace mq
