#pragma once
// What the viewport's gizmos share (the rotation rings, rotation_gizmo.h, and
// the move arrows, move_gizmo.h): handle actors in an overlay renderer on
// layer 1, so the scene never hides them, sharing the scene's camera; a
// size that stays constant on screen (a fraction of the view's half height
// at the gizmo's centre, re-read before every frame); picking one handle
// under the cursor; a highlighted handle. Subclasses build the handles and
// place them (placeHandles) from center(), size() and toCamera().

#include <vector>

#include <vtkSmartPointer.h>
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

class vtkActor;
class vtkAlgorithm;
class vtkCellPicker;
class vtkMatrix4x4;
class vtkRenderWindow;
class vtkRenderer;

namespace mq::ui {

class ViewportGizmo {
 public:
  virtual ~ViewportGizmo();
  ViewportGizmo(const ViewportGizmo&) = delete;
  ViewportGizmo& operator=(const ViewportGizmo&) = delete;

  // Puts the overlay renderer on layer 1 of `window`, sharing the camera of
  // `sceneRenderer` (re-read before every frame).
  void attach(vtkRenderWindow* window, vtkRenderer* sceneRenderer);

  void setVisible(bool visible);
  bool visible() const { return visible_; }
  // A handle that is hidden on its own (e.g. the arrows a plane cannot move along); shown by default.
  void setHandleShown(int handle, bool shown);
  // Centre and orientation (the handles' X, Y, Z are the rotated world axes).
  void setFrame(const glm::vec3& center, const glm::quat& orientation);
  glm::vec3 center() const { return center_; }
  glm::quat orientation() const { return orientation_; }
  // World space, unit: the rotated X, Y or Z axis (index 0, 1, 2).
  glm::vec3 frameAxis(int index) const;
  // World units at the current camera distance (ring radius, arrow length).
  float size() const { return size_; }
  // Unit, from the centre towards the camera.
  glm::vec3 toCamera() const { return toCamera_; }

  // The handle under display position (x, y) (pixels, origin bottom left), or -1.
  int pickHandle(int x, int y);
  // World position of the last successful pick (a point on the handle).
  glm::vec3 lastPickPosition() const { return lastPick_; }
  void setHighlightedHandle(int handle);
  int highlightedHandle() const { return highlighted_; }
  int handleCount() const { return int(handles_.size()); }
  vtkActor* handle(int index) const { return handles_[index].actor; }

 protected:
  // screenFraction: the size as a fraction of the view's half height.
  explicit ViewportGizmo(double screenFraction);
  void addHandle(vtkSmartPointer<vtkActor> actor, const double color[3]);
  void setCenter(const glm::vec3& center);
  // Sets the handles' matrices from center(), size() and toCamera().
  virtual void placeHandles() = 0;

 private:
  struct Handle {
    vtkSmartPointer<vtkActor> actor;
    double color[3];
    bool shown = true;
  };
  void syncWithCamera();
  void showHandles();

  vtkSmartPointer<vtkRenderer> overlay_;
  vtkSmartPointer<vtkRenderer> scene_;
  vtkSmartPointer<vtkCellPicker> picker_;
  std::vector<Handle> handles_;
  double screenFraction_;
  glm::vec3 center_{0.0f};
  glm::quat orientation_{1.0f, 0.0f, 0.0f, 0.0f};
  glm::vec3 lastPick_{0.0f};
  glm::vec3 toCamera_{0.0f, 0.0f, 1.0f};
  float size_ = 0.1f;
  int highlighted_ = -1;
  bool visible_ = false;
  unsigned long observer_ = 0;
};

// A handle's actor for the output of `source`: mostly ambient, no specular
// (flat, readable colours whatever the lights).
vtkSmartPointer<vtkActor> handleActor(vtkAlgorithm* source);

// The same matrix for VTK (row major).
vtkSmartPointer<vtkMatrix4x4> toVtkMatrix(const glm::mat4& m);

}  // namespace mq::ui
