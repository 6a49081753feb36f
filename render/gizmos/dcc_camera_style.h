#pragma once
// Camera navigation as in Blender and Maya, on top of VTK's trackball camera:
//   left drag or middle drag or Alt+left   orbit
//   Shift+left, Shift+middle, Alt+middle   pan
//   right drag, Ctrl+left, Alt+right       dolly
//   wheel                                  zoom
// Keys VTK binds by default to global effects (w: wireframe every actor,
// e/q: exit, 3: stereo...) are swallowed; 'f' frames the scene.

#include <functional>

#include <vtkInteractorStyleTrackballCamera.h>

namespace mq::ui {

class DccCameraStyle : public vtkInteractorStyleTrackballCamera {
 public:
  static DccCameraStyle* New();
  vtkTypeMacro(DccCameraStyle, vtkInteractorStyleTrackballCamera);

  // Called for the 'f' key (frame all).
  std::function<void()> onFrameRequested;

  void OnLeftButtonDown() override;
  void OnLeftButtonUp() override;
  void OnMiddleButtonDown() override;
  void OnMiddleButtonUp() override;
  void OnRightButtonDown() override;
  void OnRightButtonUp() override;
  void OnChar() override;
  void OnKeyPress() override {}
  void OnKeyRelease() override {}

 private:
  void startByModifiers(int defaultState);
  void endInteraction();
};

}  // namespace mq::ui
