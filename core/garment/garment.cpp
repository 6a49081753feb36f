#include "core/garment/garment.h"

#include <algorithm>
#include <set>

#include "core/garment/panel_mesher.h"
#include "core/util/error.h"

namespace mq {
namespace {

// A seam's sides share one boundary segment count so most vertices pair up
// without inserting any.
std::vector<PanelMeshOptions> meshOptions(const Garment& garment) {
  std::vector<PanelMeshOptions> options(garment.panels.size());
  for (size_t p = 0; p < garment.panels.size(); ++p) {
    options[p].targetEdgeLength = garment.targetEdgeLength;
    options[p].edgeSegments.assign(garment.panels[p].edgeCount(), 0);
  }
  for (const Seam& seam : garment.seams) {
    int pa = garment.findPanel(seam.panelA), pb = garment.findPanel(seam.panelB);
    int ea = garment.panels[pa].findEdge(seam.edgeA), eb = garment.panels[pb].findEdge(seam.edgeB);
    int segments = std::max(boundarySegments(garment.panels[pa].edgeLength(ea), garment.targetEdgeLength),
                            boundarySegments(garment.panels[pb].edgeLength(eb), garment.targetEdgeLength));
    options[pa].edgeSegments[ea] = segments;
    options[pb].edgeSegments[eb] = segments;
  }
  return options;
}

}  // namespace

int Garment::findPanel(const std::string& panelName) const {
  for (size_t p = 0; p < panels.size(); ++p)
    if (panels[p].name == panelName) return int(p);
  return -1;
}

Fabric Garment::solverFabric() const {
  if (customFabric) return *customFabric;
  if (!hasFabricPreset(fabric)) throw Error("garment '" + name + "': unknown fabric preset '" + fabric + "'");
  return fabricPreset(fabric);
}

void Garment::validate() const {
  auto fail = [&](const std::string& problem) { throw Error("garment '" + name + "': " + problem); };
  if (panels.empty()) fail("has no panels");
  if (!(targetEdgeLength > 0.0f)) fail("target edge length must be positive");
  if (targetEdgeLength > 1.0f) fail("target edge length must be at most 1 m");
  if (layer < 0 || layer > kMaxLayer) fail("layer must be from 0 to " + std::to_string(kMaxLayer));
  std::set<std::string> panelNames;
  for (const Panel& panel : panels) {
    panel.validate();
    if (!panelNames.insert(panel.name).second) fail("two panels are named '" + panel.name + "'");
  }
  // Refuse before meshing what would exhaust memory: an equilateral
  // triangle of side d covers 0.433 d^2, and there are about twice as many
  // triangles as vertices.
  double area = 0.0;
  for (const Panel& panel : panels) area += panel.area();
  const double vertices = area / (0.433 * double(targetEdgeLength) * targetEdgeLength) / 2.0;
  if (vertices > kMaxClothVertices)
    fail("would need about " + std::to_string(long(vertices)) + " cloth vertices (at most " +
         std::to_string(kMaxClothVertices) + "): make the particle distance larger");
  std::set<std::pair<int, int>> sewn;
  for (const Seam& seam : seams) {
    std::string label = "seam " + seam.panelA + ":" + seam.edgeA + " - " + seam.panelB + ":" + seam.edgeB;
    int pa = findPanel(seam.panelA), pb = findPanel(seam.panelB);
    if (pa < 0) fail(label + " names an unknown panel '" + seam.panelA + "'");
    if (pb < 0) fail(label + " names an unknown panel '" + seam.panelB + "'");
    int ea = panels[pa].findEdge(seam.edgeA), eb = panels[pb].findEdge(seam.edgeB);
    if (ea < 0) fail(label + " names an unknown edge '" + seam.edgeA + "' of panel '" + seam.panelA + "'");
    if (eb < 0) fail(label + " names an unknown edge '" + seam.edgeB + "' of panel '" + seam.panelB + "'");
    if (pa == pb && ea == eb) fail(label + " sews an edge to itself");
    if (!sewn.insert({pa, ea}).second || !sewn.insert({pb, eb}).second) fail(label + " uses an edge already sewn");
  }
}

std::vector<SeamLengths> seamLengths(const Garment& garment) {
  garment.validate();
  std::vector<SeamLengths> lengths;
  for (const Seam& seam : garment.seams) {
    const Panel& a = garment.panels[garment.findPanel(seam.panelA)];
    const Panel& b = garment.panels[garment.findPanel(seam.panelB)];
    lengths.push_back({a.edgeLength(a.findEdge(seam.edgeA)), b.edgeLength(b.findEdge(seam.edgeB))});
  }
  return lengths;
}

GarmentMesh buildGarmentMesh(const Garment& garment) {
  garment.validate();
  std::vector<PanelMeshOptions> options = meshOptions(garment);
  std::vector<PanelMesh> meshes;
  for (size_t p = 0; p < garment.panels.size(); ++p) meshes.push_back(meshPanel(garment.panels[p], options[p]));

  // Pair seams first: pairing may insert boundary vertices.
  float matchDistance = 0.3f * garment.targetEdgeLength;
  std::vector<std::vector<VertexPair>> localPairs;
  std::vector<std::pair<int, int>> seamPanels;
  for (const Seam& seam : garment.seams) {
    int pa = garment.findPanel(seam.panelA), pb = garment.findPanel(seam.panelB);
    localPairs.push_back(pairSeamVertices(meshes[pa], garment.panels[pa].findEdge(seam.edgeA), meshes[pb],
                                          garment.panels[pb].findEdge(seam.edgeB), seam.reversed, matchDistance));
    seamPanels.push_back({pa, pb});
  }

  GarmentMesh out;
  for (size_t p = 0; p < meshes.size(); ++p) {
    uint32_t first = uint32_t(out.vertexCount());
    out.panelFirstVertex.push_back(first);
    const PanelPlacement& placement = garment.panels[p].placement;
    for (glm::vec2 uv : meshes[p].vertices) {
      glm::vec3 x = placement.place(uv);
      out.positions.insert(out.positions.end(), {x.x, x.y, x.z});
      out.restUvs.insert(out.restUvs.end(), {uv.x, uv.y});
      out.panelIds.push_back(uint16_t(p));
    }
    for (uint32_t i : meshes[p].triangles) out.triangles.push_back(first + i);
  }
  for (size_t s = 0; s < localPairs.size(); ++s) {
    uint32_t offsetA = out.panelFirstVertex[seamPanels[s].first], offsetB = out.panelFirstVertex[seamPanels[s].second];
    for (auto [a, b] : localPairs[s]) out.seamPairs.push_back({offsetA + a, offsetB + b});
  }
  return out;
}

}  // namespace mq
