// The only translation unit that includes CGAL's 2D mesher (slow to compile).
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <map>

#include "core/garment/panel_mesher.h"
#include "core/util/error.h"

namespace mq {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Delaunay_mesh_vertex_base_2<Kernel>;
using FaceBase = CGAL::Delaunay_mesh_face_base_2<Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_predicates_tag>;
using Criteria = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;
using Mesher = CGAL::Delaunay_mesher_2<Cdt, Criteria>;
using VertexHandle = Cdt::Vertex_handle;

// Aspect bound B = 1 / (4 sin^2 minAngle): 0.125 keeps angles above 20.7 degrees.
constexpr double kShapeBound = 0.125;

// One boundary sample of the input outline: which panel edge, how far along it.
struct BoundarySample {
  int edge;
  float arcLength;
  bool corner;
};

struct SampledOutline {
  std::vector<glm::vec2> points;
  std::vector<BoundarySample> samples;
  std::vector<float> edgeLengths;
};

SampledOutline sampleOutline(const Panel& panel, const PanelMeshOptions& options) {
  SampledOutline outline;
  for (int e = 0; e < panel.edgeCount(); ++e) {
    float length = panel.edgeLength(e);
    outline.edgeLengths.push_back(length);
    int segments = e < int(options.edgeSegments.size()) && options.edgeSegments[e] > 0
                       ? options.edgeSegments[e]
                       : boundarySegments(length, options.targetEdgeLength);
    std::vector<glm::vec2> points = panel.sampleEdge(e, segments);
    for (int i = 0; i < segments; ++i) {  // the end corner is the next edge's start
      outline.points.push_back(points[i]);
      outline.samples.push_back({e, length * float(i) / float(segments), i == 0});
    }
  }
  return outline;
}

Cdt::Point toPoint(glm::vec2 p) { return Cdt::Point(p.x, p.y); }
glm::vec2 toVec(const Cdt::Point& p) { return {float(p.x()), float(p.y())}; }

// Walks the domain boundary counter-clockwise (domain on the left).
std::map<VertexHandle, VertexHandle> boundaryNext(const Cdt& cdt) {
  std::map<VertexHandle, VertexHandle> next;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->is_in_domain()) continue;
    for (int i = 0; i < 3; ++i) {
      auto neighbour = f->neighbor(i);
      if (!cdt.is_infinite(neighbour) && neighbour->is_in_domain()) continue;
      next[f->vertex(f->ccw(i))] = f->vertex(f->cw(i));
    }
  }
  return next;
}

}  // namespace

// Boundary pieces a little shorter than the bound: a piece at exactly the
// bound (or a rounding error above it) makes every triangle on it "too big",
// and the mesher would split the whole boundary in halves.
int boundarySegments(float length, float targetEdgeLength) {
  return std::max(1, int(std::ceil(length / (0.9f * targetEdgeLength))));
}

PanelMesh meshPanel(const Panel& panel, const PanelMeshOptions& options) {
  panel.validate();
  if (!(options.targetEdgeLength > 0.0f))
    throw Error("panel '" + panel.name + "': target edge length must be positive");
  SampledOutline outline = sampleOutline(panel, options);

  Cdt cdt;
  std::vector<VertexHandle> inputVertices;
  for (glm::vec2 p : outline.points) inputVertices.push_back(cdt.insert(toPoint(p)));
  for (size_t i = 0; i < inputVertices.size(); ++i)
    cdt.insert_constraint(inputVertices[i], inputVertices[(i + 1) % inputVertices.size()]);
  std::map<VertexHandle, size_t> sampleOf;
  for (size_t i = 0; i < inputVertices.size(); ++i) sampleOf[inputVertices[i]] = i;
  if (sampleOf.size() != inputVertices.size())
    throw Error("panel '" + panel.name + "': outline touches itself at the target edge length");

  Mesher mesher(cdt, Criteria(kShapeBound, options.targetEdgeLength));
  mesher.refine_mesh();

  PanelMesh mesh;
  std::map<VertexHandle, uint32_t> index;
  auto indexOf = [&](VertexHandle v) {
    auto [it, inserted] = index.try_emplace(v, uint32_t(mesh.vertices.size()));
    if (inserted) mesh.vertices.push_back(toVec(v->point()));
    return it->second;
  };
  for (VertexHandle v : inputVertices) indexOf(v);  // corners and samples first, in outline order
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->is_in_domain()) continue;
    for (int i = 0; i < 3; ++i) mesh.triangles.push_back(indexOf(f->vertex(i)));
  }

  // Boundary vertices per edge: input samples, plus any point the mesher
  // inserted on a boundary segment (its arc length measured along the chord).
  std::map<VertexHandle, VertexHandle> next = boundaryNext(cdt);
  mesh.edgeVertices.assign(panel.edgeCount(), {});
  mesh.edgeArcLengths.assign(panel.edgeCount(), {});
  VertexHandle start = inputVertices.front(), v = start;
  size_t lastSample = 0;
  float lastArc = 0.0f;
  glm::vec2 lastPoint = outline.points[0];
  size_t guard = 0;
  do {
    auto sample = sampleOf.find(v);
    if (sample != sampleOf.end()) {
      const BoundarySample& s = outline.samples[sample->second];
      if (s.corner && sample->second != 0) {  // close the previous edge at this corner
        mesh.edgeVertices[s.edge - 1].push_back(index[v]);
        mesh.edgeArcLengths[s.edge - 1].push_back(outline.edgeLengths[s.edge - 1]);
      }
      lastSample = sample->second;
      lastArc = s.arcLength;
      mesh.edgeVertices[s.edge].push_back(index[v]);
      mesh.edgeArcLengths[s.edge].push_back(s.arcLength);
    } else {
      int edge = outline.samples[lastSample].edge;
      lastArc += glm::length(toVec(v->point()) - lastPoint);
      mesh.edgeVertices[edge].push_back(index[v]);
      mesh.edgeArcLengths[edge].push_back(lastArc);
    }
    lastPoint = toVec(v->point());
    auto it = next.find(v);
    if (it == next.end() || ++guard > 10 * index.size())
      throw Error("panel '" + panel.name + "': the meshed boundary is not one closed loop");
    v = it->second;
  } while (v != start);
  mesh.edgeVertices.back().push_back(index[start]);
  mesh.edgeArcLengths.back().push_back(outline.edgeLengths.back());
  return mesh;
}

}  // namespace mq
