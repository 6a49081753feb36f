#pragma once
// A garment: pattern panels (each with its placement around the body) and the
// seams that sew them. buildGarmentMesh meshes the panels, pairs the seam
// vertices and places everything in 3D: the cloth solver's input.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/garment/fabric.h"
#include "core/garment/panel.h"
#include "core/garment/seam.h"
#include "core/mesh/mesh.h"

namespace mq {

// How a built-in garment was made, so an editor can change a measurement and
// rebuild it (see parametric_garments.h). Empty type: hand-made panels.
struct ParametricRecipe {
  std::string type;
  std::map<std::string, float> parameters;
};

// Garment vertices held by the simulation: fixed in space, or following the
// nearest body vertex. Indices are garment-mesh vertices (buildGarmentMesh).
struct GarmentPins {
  enum class Attach { Body, Space };
  std::vector<uint32_t> vertices;
  Attach attach = Attach::Body;
};

struct Garment {
  std::string name;
  std::vector<Panel> panels;
  std::vector<Seam> seams;
  std::string fabric = "cotton";  // the fabric preset ("" = custom: customFabric alone)
  // Values of a document's own fabric ("fabric": {"preset": .., "stretch": ..});
  // none: the preset's.
  std::optional<Fabric> customFabric;
  GarmentPins pins;
  float targetEdgeLength = 0.02f;  // metres
  ParametricRecipe recipe;
  // Layering (sim/garment/garment_layers.h): a garment is worn over those of
  // lower layers, and over those of its own layer earlier in the list.
  int layer = 0;
  static constexpr int kMaxLayer = 99;
  // The largest cloth a garment may mesh into (memory, and minutes a frame).
  static constexpr long kMaxClothVertices = 400000;

  int findPanel(const std::string& panelName) const;  // -1 if absent
  // The fabric the solver uses: customFabric, else the preset (mq::Error if unknown).
  Fabric solverFabric() const;
  // Throws mq::Error naming the garment and the problem: invalid panels,
  // duplicate panel names, seams naming unknown panels or edges, an edge in
  // two seams, a seam sewing an edge to itself.
  void validate() const;
};

// The arc lengths (metres) of the two edges a seam sews, per seam, for a
// pattern check: edges of different lengths ease (a sleeve cap into its
// armhole) or pucker. Throws mq::Error for an invalid garment.
struct SeamLengths {
  float a = 0.0f, b = 0.0f;
};
std::vector<SeamLengths> seamLengths(const Garment& garment);

// The meshed, placed garment: one triangle mesh over all panels.
struct GarmentMesh {
  std::vector<float> positions;            // 3 per vertex: world space around the rest-pose body
  std::vector<float> restUvs;              // 2 per vertex: pattern coordinates in metres
  std::vector<uint32_t> triangles;         // 3 per triangle, facing outwards
  std::vector<uint16_t> panelIds;          // per vertex: index into Garment::panels
  std::vector<VertexPair> seamPairs;       // vertices to sew together
  std::vector<uint32_t> panelFirstVertex;  // per panel: its first vertex (panels are contiguous)

  size_t vertexCount() const { return positions.size() / 3; }
  size_t triangleCount() const { return triangles.size() / 3; }
  glm::vec3 position(size_t v) const { return {positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]}; }
  // A renderable mesh: positions, normals, and the rest UVs as texture coordinates.
};

// Throws mq::Error (from validate or the mesher) when the garment is invalid.
GarmentMesh buildGarmentMesh(const Garment& garment);

}  // namespace mq
