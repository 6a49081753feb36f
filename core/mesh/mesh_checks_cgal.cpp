// The CGAL part of mesh_checks.h, kept in its own translation unit (slow to compile).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <iterator>
#include <stdexcept>

#include "core/mesh/mesh_checks.h"

namespace mq {

std::vector<std::pair<size_t, size_t>> selfIntersections(const std::vector<float>& positions,
                                                         const std::vector<uint32_t>& triangles) {
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;
  using Face = SurfaceMesh::Face_index;
  SurfaceMesh mesh;
  std::vector<SurfaceMesh::Vertex_index> vertices;
  for (size_t v = 0; v + 2 < positions.size(); v += 3)
    vertices.push_back(mesh.add_vertex(Kernel::Point_3(positions[v], positions[v + 1], positions[v + 2])));
  for (size_t t = 0; t + 2 < triangles.size(); t += 3)
    if (mesh.add_face(vertices[triangles[t]], vertices[triangles[t + 1]], vertices[triangles[t + 2]]) ==
        SurfaceMesh::null_face())
      throw std::invalid_argument("selfIntersections: the mesh is not 2-manifold");
  std::vector<std::pair<Face, Face>> pairs;
  CGAL::Polygon_mesh_processing::self_intersections(mesh, std::back_inserter(pairs));
  std::vector<std::pair<size_t, size_t>> result;
  for (const auto& [a, b] : pairs) result.emplace_back(size_t(a), size_t(b));
  return result;
}

}  // namespace mq
