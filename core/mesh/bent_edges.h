#pragma once
// How crinkled a cloth surface looks: the share of its interior edges (two
// triangles) whose triangles meet more than a given angle away from flat.
// Cloth that buckles makes a few smooth folds (few bent edges); cloth whose
// springs resist compression as hard as tension shortens in plane and
// crinkles at the particle scale (many). Positions that are bit-equal count
// as one vertex, so a welded seam is interior, not a border.

#include <cstdint>
#include <vector>

namespace mq {

struct BentEdges {
  int interiorEdges = 0;
  int bent = 0;  // interior edges bent more than the angle
  float share() const { return interiorEdges > 0 ? float(bent) / float(interiorEdges) : 0.0f; }
};

// positions: 3 floats per vertex; triangles: 3 indices each. Edges shared by
// more than two triangles, and degenerate triangles, are left out.
BentEdges bentEdges(const std::vector<float>& positions, const std::vector<uint32_t>& triangles, float degrees);

}  // namespace mq
