#include <algorithm>
#include <string>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include "core/mesh/boundary_loops.h"
#include "core/util/error.h"

namespace mq {
namespace {

using HalfEdgeMesh = OpenMesh::TriMesh_ArrayKernelT<>;

// Connectivity only: positions do not matter for the rims.
HalfEdgeMesh connectivityOf(size_t vertexCount, const std::vector<uint32_t>& triangles) {
  HalfEdgeMesh mesh;
  mesh.reserve(vertexCount, triangles.size(), triangles.size() / 3);
  for (size_t v = 0; v < vertexCount; ++v) mesh.add_vertex(HalfEdgeMesh::Point(0, 0, 0));
  for (size_t t = 0; t + 2 < triangles.size(); t += 3) {
    const uint32_t a = triangles[t], b = triangles[t + 1], c = triangles[t + 2];
    if (a >= vertexCount || b >= vertexCount || c >= vertexCount)
      throw Error("triangle " + std::to_string(t / 3) + " names a vertex beyond the " + std::to_string(vertexCount) +
                  " vertices");
    const auto face = mesh.add_face(mesh.vertex_handle(a), mesh.vertex_handle(b), mesh.vertex_handle(c));
    if (!face.is_valid())
      throw Error("triangle " + std::to_string(t / 3) + " makes the surface non-manifold, so it has no boundary loops");
  }
  return mesh;
}

}  // namespace

std::vector<std::vector<uint32_t>> boundaryLoops(size_t vertexCount, const std::vector<uint32_t>& triangles) {
  const HalfEdgeMesh mesh = connectivityOf(vertexCount, triangles);
  std::vector<bool> walked(mesh.n_halfedges(), false);
  std::vector<std::vector<uint32_t>> loops;
  for (const auto start : mesh.halfedges()) {
    if (!mesh.is_boundary(start) || walked[start.idx()]) continue;
    std::vector<uint32_t> loop;
    for (auto h = start; !walked[h.idx()]; h = mesh.next_halfedge_handle(h)) {
      walked[h.idx()] = true;
      loop.push_back(uint32_t(mesh.from_vertex_handle(h).idx()));
    }
    std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
    loops.push_back(std::move(loop));
  }
  std::sort(loops.begin(), loops.end(), [](const auto& a, const auto& b) { return a.front() < b.front(); });
  return loops;
}

}  // namespace mq
