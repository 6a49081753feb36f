#pragma once
// The signed distance to a triangle mesh, sampled on a regular grid over a
// region: what hair keeps out of when the body is a scanned surface rather
// than a few shapes. Distances are exact (to the closest triangle) within a
// band around the surface; beyond it the field holds the band's value with
// the sign of the nearest band point. Negative inside: the side of the
// closest point's interpolated vertex normal, and a closest point on an open
// edge (a scan cut at the neck) counts as outside. Trilinear between grid
// points, so the field and its gradient are continuous. Queries are const and
// may run on several threads.

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "core/mesh/mesh.h"

namespace mq {

class MeshDistanceField {
 public:
  // The mesh as flat arrays; `region` is the box covered, `cell` the grid
  // spacing, `band` how far from the surface distances are exact (at least
  // two cells).
  MeshDistanceField(const std::vector<float>& positions, const std::vector<uint32_t>& triangles, const Aabb& region,
                    float cell, float band);

  // Signed distance at p, clamped to [-band, band]; +band outside the region.
  float distance(const glm::vec3& p) const;
  // Unit direction of the field's increase at p (outward); zero where the
  // field is flat (far from the surface).
  glm::vec3 outward(const glm::vec3& p) const;
  // Moves p along the outward direction until it is at least `margin` from
  // the surface on the outside; returns true when it moved. `normal`, if
  // given, receives the outward direction where it moved.
  bool pushOut(glm::vec3& p, float margin, glm::vec3* normal = nullptr) const;

  float band() const { return band_; }
  float cell() const { return cell_; }

 private:
  size_t index(int x, int y, int z) const { return (size_t(z) * dims_.y + y) * dims_.x + x; }
  void sampleBand(const std::vector<float>& positions, const std::vector<uint32_t>& triangles,
                  std::vector<uint8_t>& known);
  void signBeyondBand(std::vector<uint8_t>& known);

  glm::vec3 origin_{0.0f};
  float cell_ = 1.0f;
  float band_ = 0.0f;
  glm::ivec3 dims_{0};
  std::vector<float> values_;
};

}  // namespace mq
