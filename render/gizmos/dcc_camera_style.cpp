#include "render/gizmos/dcc_camera_style.h"

#include <vtkCallbackCommand.h>
#include <vtkObjectFactory.h>
#include <vtkRenderWindowInteractor.h>

namespace mq::ui {

vtkStandardNewMacro(DccCameraStyle);

void DccCameraStyle::startByModifiers(int defaultState) {
  vtkRenderWindowInteractor* rwi = Interactor;
  FindPokedRenderer(rwi->GetEventPosition()[0], rwi->GetEventPosition()[1]);
  if (!CurrentRenderer) return;
  GrabFocus(EventCallbackCommand);
  int state = defaultState;
  if (rwi->GetShiftKey())
    state = VTKIS_PAN;
  else if (rwi->GetControlKey())
    state = VTKIS_DOLLY;
  StartState(state);
}

void DccCameraStyle::endInteraction() {
  switch (State) {
    case VTKIS_ROTATE:
      EndRotate();
      break;
    case VTKIS_PAN:
      EndPan();
      break;
    case VTKIS_DOLLY:
      EndDolly();
      break;
    case VTKIS_SPIN:
      EndSpin();
      break;
    default:
      break;
  }
  if (Interactor) ReleaseFocus();
}

void DccCameraStyle::OnLeftButtonDown() { startByModifiers(VTKIS_ROTATE); }
void DccCameraStyle::OnLeftButtonUp() { endInteraction(); }

void DccCameraStyle::OnMiddleButtonDown() {
  // Blender orbits with the middle button; Maya pans with Alt+middle.
  startByModifiers(Interactor->GetAltKey() ? VTKIS_PAN : VTKIS_ROTATE);
}
void DccCameraStyle::OnMiddleButtonUp() { endInteraction(); }

void DccCameraStyle::OnRightButtonDown() { startByModifiers(VTKIS_DOLLY); }
void DccCameraStyle::OnRightButtonUp() { endInteraction(); }

void DccCameraStyle::OnChar() {
  const char key = Interactor->GetKeyCode();
  if ((key == 'f' || key == 'F') && onFrameRequested) onFrameRequested();
}

}  // namespace mq::ui
