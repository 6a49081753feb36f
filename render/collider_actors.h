#pragma once
// The scene's primitive colliders drawn in the viewport: one translucent
// actor per collider (a sphere, a capsule, a finite square of the plane with
// its normal), the selected one brighter. Rebuilt from the colliders on
// every edit; the colliders are few, so that is cheap. pick() finds the
// collider under the cursor (the character or cloth in front of it hides it).

#include <vector>

#include <vtkSmartPointer.h>

#include "core/geometry/solid_primitive.h"

class vtkActor;
class vtkPolyData;

namespace mq::render {

class SceneView;

// The surface of a collider as triangles (a plane: a square of `planeSize`
// metres around its point). For drawing and for tests of the drawing.
vtkSmartPointer<vtkPolyData> colliderSurface(const SolidPrimitive& collider, double planeSize = 2.0);

class ColliderActors {
 public:
  explicit ColliderActors(SceneView* view);
  ~ColliderActors();
  ColliderActors(const ColliderActors&) = delete;
  ColliderActors& operator=(const ColliderActors&) = delete;

  // selected: index into colliders, -1 for none.
  void set(const std::vector<SolidPrimitive>& colliders, int selected);
  void setVisible(bool visible);
  size_t count() const { return actors_.size(); }
  vtkActor* actor(size_t i) const { return actors_[i]; }
  // The collider drawn under display position (x, y) (pixels, origin bottom
  // left), nearest the viewer; -1 for none, or when the character's surface
  // or one of the `occluders` (the cloth) is nearer there. Needs the
  // renderer in a window.
  int pick(int x, int y, const std::vector<vtkActor*>& occluders = {}) const;

 private:
  SceneView* view_;
  std::vector<vtkSmartPointer<vtkActor>> actors_;
  bool visible_ = true;
};

}  // namespace mq::render
