#pragma once
// The floor under the character (at y = 0 unless moved): a subtle line grid on a soft disc
// that fades into the backdrop, and a blurred contact shadow under the feet
// so the character reads as standing on the floor.

#include <memory>

#include "core/mesh/mesh.h"

class vtkRenderer;

namespace mq::render {

class Ground {
 public:
  Ground();
  ~Ground();

  void addTo(vtkRenderer* renderer);
  // Sizes the grid to `characterBounds` and places the contact shadow over
  // `footprint` (the xz bounds of the vertices near the floor).
  void fit(const Aabb& characterBounds, const Aabb& footprint);
  // Moves the contact shadow under the posed feet (cheap: once per frame).
  void placeShadow(const Aabb& footprint);
  void setVisible(bool visible);
  // The floor's height (y): the grid, disc and shadow move together.
  void setHeight(double y);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mq::render
