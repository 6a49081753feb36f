#pragma once
// Per-vertex tangent frames for normal maps, over flat arrays.

#include <cstdint>
#include <vector>

namespace mq {

// Tangents from texture coordinates (Lengyel, "Computing tangent space basis
// vectors for an arbitrary mesh", 2001): per triangle, the directions of
// increasing u and v, summed per vertex, orthogonalised against the normal.
// Out: 4 floats per vertex: unit tangent (direction of increasing u) and the
// handedness w, as glTF's TANGENT: bitangent = cross(normal, tangent) * w
// points to the image's top, i.e. decreasing v (uvs with a top-left origin).
// A vertex whose triangles have degenerate uvs gets any unit tangent
// perpendicular to its normal.
void computeVertexTangents(const std::vector<float>& positions, const std::vector<float>& normals,
                           const std::vector<float>& uvs, const std::vector<uint32_t>& triangles,
                           std::vector<float>& tangents);

// Carries rest tangents to a posed surface: each is turned by the smallest
// rotation taking its vertex's rest normal to the posed normal, then made
// perpendicular to the posed normal again. Cheaper than re-deriving them
// from uvs every frame, and it keeps the file's own tangents.
void carryTangents(const std::vector<float>& restNormals, const std::vector<float>& restTangents,
                   const std::vector<float>& posedNormals, std::vector<float>& posedTangents);

}  // namespace mq
