#pragma once
// A seam sews one panel edge to another (or to another edge of the same
// panel, like a sleeve's underarm). Both sides are resampled so they carry the
// same number of boundary vertices at matching normalised arc length; the
// result is a list of vertex pairs that the cloth pulls together and welds.

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/garment/panel_mesher.h"

namespace mq {

struct Seam {
  std::string panelA, edgeA;
  std::string panelB, edgeB;
  // B runs from its end corner to its start corner along A: the usual case
  // for two counter-clockwise panels whose outsides face out.
  bool reversed = true;
};

using VertexPair = std::pair<uint32_t, uint32_t>;

// Pairs the vertices of edge `edgeA` of `meshA` with those of `edgeB` of
// `meshB` (which may be the same mesh), in order from A's start corner.
// Where one side has a vertex with no partner within `matchDistance`
// (metres of arc length), the other side's boundary segment is split there.
std::vector<VertexPair> pairSeamVertices(PanelMesh& meshA, int edgeA, PanelMesh& meshB, int edgeB, bool reversed,
                                         float matchDistance);

}  // namespace mq
