#include "ui/viewport/vtk_viewport_widget.h"

#include <utility>
#include <vector>

#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QSurfaceFormat>
#include <QTimer>
#include <QWheelEvent>

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkOpenGLState.h>
#include <vtkProp.h>
#include <vtkPropCollection.h>
#include <vtkRenderer.h>
#include <vtkRendererCollection.h>

#include "render/gizmos/dcc_camera_style.h"

namespace mq::ui {

VtkViewportWidget::VtkViewportWidget(QWidget* parent)
    : QOpenGLWidget(parent),
      renderWindow_(vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New()),
      interactor_(vtkSmartPointer<vtkGenericRenderWindowInteractor>::New()) {
  setFocusPolicy(Qt::StrongFocus);
  setMouseTracking(true);
  setMinimumSize(160, 120);

  // Qt owns the context and the final framebuffer; VTK renders into its own
  // framebuffer and we blit it ourselves in paintGL.
  renderWindow_->SetFrameBlitModeToNoBlit();
  renderWindow_->SetOwnContext(false);
  renderWindow_->SetReadyForRendering(false);
  renderWindow_->SetMultiSamples(0);
  connectWindowCallbacks();

  renderWindow_->SetInteractor(interactor_);
  interactor_->SetRenderWindow(renderWindow_);
  // Interactions ask for a repaint instead of rendering outside paintGL.
  interactor_->EnableRenderOff();
  vtkNew<vtkCallbackCommand> onRender;
  onRender->SetClientData(this);
  onRender->SetCallback(
      [](vtkObject*, unsigned long, void* self, void*) { static_cast<VtkViewportWidget*>(self)->requestRender(); });
  interactor_->AddObserver(vtkCommand::RenderEvent, onRender);

  auto style = vtkSmartPointer<DccCameraStyle>::New();
  style->onFrameRequested = [this] {
    if (auto* renderer = renderWindow_->GetRenderers()->GetFirstRenderer()) renderer->ResetCamera();
    requestRender();
  };
  cameraStyle_ = style;
  interactor_->SetInteractorStyle(style);
}

VtkViewportWidget::~VtkViewportWidget() {
  // Release VTK's GL resources while the context still exists.
  if (glInitialized_ && context()) {
    makeCurrent();
    renderWindow_->Finalize();
    doneCurrent();
  }
}

QSurfaceFormat VtkViewportWidget::defaultFormat() {
  QSurfaceFormat format;
  format.setRenderableType(QSurfaceFormat::OpenGL);
  format.setVersion(3, 2);
  format.setProfile(QSurfaceFormat::CoreProfile);
  format.setSwapBehavior(QSurfaceFormat::DoubleBuffer);
  format.setRedBufferSize(8);
  format.setGreenBufferSize(8);
  format.setBlueBufferSize(8);
  format.setAlphaBufferSize(8);
  format.setDepthBufferSize(24);
  format.setStencilBufferSize(8);
  format.setSamples(0);  // deterministic images for tests
  return format;
}

vtkGenericOpenGLRenderWindow* VtkViewportWidget::renderWindow() const { return renderWindow_; }
vtkGenericRenderWindowInteractor* VtkViewportWidget::interactor() const { return interactor_; }

void VtkViewportWidget::addRenderer(vtkRenderer* renderer) {
  renderWindow_->AddRenderer(renderer);
  requestRender();
}

void VtkViewportWidget::requestRender() {
  fullFramePending_ = true;
  update();
}

void VtkViewportWidget::requestContinuation(vtkProp* prop) {
  if (fullFramePending_) return;  // a full frame is on its way
  continuation_ = prop;
  // Through the timer queue rather than a posted paint, which Qt would
  // serve before the input and timers waiting since the last frame.
  QTimer::singleShot(0, this, [this] {
    if (continuation_) update();
  });
}

void VtkViewportWidget::connectWindowCallbacks() {
  vtkNew<vtkCallbackCommand> callback;
  callback->SetClientData(this);
  callback->SetCallback([](vtkObject* caller, unsigned long id, void* self, void* data) {
    static_cast<VtkViewportWidget*>(self)->onWindowEvent(caller, id, data);
  });
  renderWindow_->AddObserver(vtkCommand::WindowMakeCurrentEvent, callback);
  renderWindow_->AddObserver(vtkCommand::WindowIsCurrentEvent, callback);
  renderWindow_->AddObserver(vtkCommand::WindowSupportsOpenGLEvent, callback);
  renderWindow_->AddObserver(vtkCommand::WindowIsDirectEvent, callback);
}

void VtkViewportWidget::onWindowEvent(vtkObject*, unsigned long eventId, void* callData) {
  QOpenGLContext* ctx = context();
  switch (eventId) {
    case vtkCommand::WindowMakeCurrentEvent:
      // Not QOpenGLWidget::makeCurrent(): that re-binds Qt's framebuffer
      // behind VTK's binding cache and VTK would attach to the wrong FBO.
      if (ctx && QOpenGLContext::currentContext() != ctx) ctx->makeCurrent(ctx->surface());
      break;
    case vtkCommand::WindowIsCurrentEvent:
      *static_cast<bool*>(callData) = ctx && QOpenGLContext::currentContext() == ctx;
      break;
    case vtkCommand::WindowSupportsOpenGLEvent:
      *static_cast<int*>(callData) = 1;
      break;
    case vtkCommand::WindowIsDirectEvent:
      *static_cast<int*>(callData) = 1;
      break;
    default:
      break;
  }
}

void VtkViewportWidget::initializeGL() {
  renderWindow_->SetReadyForRendering(true);
  renderWindow_->OpenGLInitContext();
  glInitialized_ = true;
  const qreal ratio = devicePixelRatioF();
  renderWindow_->SetSize(int(width() * ratio), int(height() * ratio));
  if (!interactor_->GetInitialized()) {
    interactor_->SetSize(int(width() * ratio), int(height() * ratio));
    interactor_->Initialize();
  }
}

void VtkViewportWidget::resizeGL(int w, int h) {
  fullFramePending_ = true;
  const qreal ratio = devicePixelRatioF();
  const int pw = int(w * ratio), ph = int(h * ratio);
  renderWindow_->SetSize(pw, ph);
  interactor_->UpdateSize(pw, ph);
  interactor_->InvokeEvent(vtkCommand::ConfigureEvent, nullptr);
}

void VtkViewportWidget::paintGL() {
  vtkOpenGLState* state = renderWindow_->GetState();
  state->Reset();
  state->ResetFramebufferBindings();
  state->Push();
  // Qt leaves GL_LESS; VTK expects GL_LEQUAL.
  state->vtkglDepthFunc(GL_LEQUAL);
  if (continuation_ && !fullFramePending_)
    renderContinuation(continuation_);
  else
    renderWindow_->Render();
  fullFramePending_ = false;
  continuation_ = nullptr;

  const qreal ratio = devicePixelRatioF();
  const int pw = int(width() * ratio), ph = int(height() * ratio);
  state->vtkglBindFramebuffer(GL_DRAW_FRAMEBUFFER, defaultFramebufferObject());
  QOpenGLContext::currentContext()->functions()->glDisable(GL_SCISSOR_TEST);
  const int* size = renderWindow_->GetSize();
  renderWindow_->BlitDisplayFramebuffer(0, 0, 0, size[0], size[1], 0, 0, pw, ph, GL_COLOR_BUFFER_BIT, GL_LINEAR);
  clearAlpha();
  state->Pop();
  emit frameRendered();
}

// VTK renders into its own framebuffer, which keeps the last frame's colour
// and depth: with the renderers' erase off and every other prop of the scene
// layer hidden, `prop` draws over that frame, behind what is in front of it.
// Overlay layers (gizmos) draw again on top as in a full frame.
void VtkViewportWidget::renderContinuation(vtkProp* prop) {
  std::vector<std::pair<vtkRenderer*, bool>> erase;
  std::vector<std::pair<vtkProp*, vtkTypeBool>> visibility;
  vtkRendererCollection* renderers = renderWindow_->GetRenderers();
  renderers->InitTraversal();
  while (vtkRenderer* renderer = renderers->GetNextItem()) {
    if (renderer->GetLayer() > 0) continue;
    erase.emplace_back(renderer, renderer->GetErase());
    renderer->EraseOff();
    vtkPropCollection* props = renderer->GetViewProps();
    props->InitTraversal();
    while (vtkProp* other = props->GetNextProp()) {
      if (other == prop) continue;
      visibility.emplace_back(other, other->GetVisibility());
      other->VisibilityOff();
    }
  }
  renderWindow_->Render();
  for (auto [other, visible] : visibility) other->SetVisibility(visible);
  for (auto [renderer, wasErasing] : erase) renderer->SetErase(wasErasing);
}

void VtkViewportWidget::clearAlpha() {
  // Mesa composites the widget with its alpha; force it opaque.
  vtkOpenGLState* state = renderWindow_->GetState();
  state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
  state->vtkglClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  state->vtkglClear(GL_COLOR_BUFFER_BIT);
  state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

// --- events -----------------------------------------------------------------

void VtkViewportWidget::setEventInformation(const QPointF& position, Qt::KeyboardModifiers modifiers, int repeat) {
  const qreal ratio = devicePixelRatioF();
  interactor_->SetEventInformationFlipY(int(position.x() * ratio), int(position.y() * ratio),
                                        (modifiers & Qt::ControlModifier) ? 1 : 0,
                                        (modifiers & Qt::ShiftModifier) ? 1 : 0, 0, repeat);
  interactor_->SetAltKey((modifiers & Qt::AltModifier) ? 1 : 0);
}

void VtkViewportWidget::mousePressEvent(QMouseEvent* event) {
  setFocus(Qt::MouseFocusReason);
  setEventInformation(event->position(), event->modifiers());
  switch (event->button()) {
    case Qt::LeftButton:
      interactor_->LeftButtonPressEvent();
      break;
    case Qt::MiddleButton:
      interactor_->MiddleButtonPressEvent();
      break;
    case Qt::RightButton:
      interactor_->RightButtonPressEvent();
      break;
    default:
      return;
  }
  event->accept();
}

void VtkViewportWidget::mouseMoveEvent(QMouseEvent* event) {
  setEventInformation(event->position(), event->modifiers());
  interactor_->MouseMoveEvent();
  event->accept();
}

void VtkViewportWidget::mouseReleaseEvent(QMouseEvent* event) {
  setEventInformation(event->position(), event->modifiers());
  switch (event->button()) {
    case Qt::LeftButton:
      interactor_->LeftButtonReleaseEvent();
      break;
    case Qt::MiddleButton:
      interactor_->MiddleButtonReleaseEvent();
      break;
    case Qt::RightButton:
      interactor_->RightButtonReleaseEvent();
      break;
    default:
      return;
  }
  event->accept();
}

void VtkViewportWidget::mouseDoubleClickEvent(QMouseEvent* event) {
  // VTK detects double clicks from the repeat count of a press.
  setEventInformation(event->position(), event->modifiers(), 1);
  if (event->button() == Qt::LeftButton) interactor_->LeftButtonPressEvent();
  event->accept();
}

void VtkViewportWidget::wheelEvent(QWheelEvent* event) {
  setEventInformation(event->position(), event->modifiers());
  const int delta = event->angleDelta().y();
  if (delta > 0)
    interactor_->MouseWheelForwardEvent();
  else if (delta < 0)
    interactor_->MouseWheelBackwardEvent();
  event->accept();
}

void VtkViewportWidget::keyPressEvent(QKeyEvent* event) {
  const QPointF cursor = mapFromGlobal(QCursor::pos());
  setEventInformation(cursor, event->modifiers(), event->isAutoRepeat() ? 1 : 0);
  const QString text = event->text();
  interactor_->SetKeyCode(text.isEmpty() ? 0 : text.at(0).toLatin1());
  interactor_->SetKeySym(text.isEmpty() ? nullptr : text.toLatin1().constData());
  interactor_->KeyPressEvent();
  interactor_->CharEvent();
  QOpenGLWidget::keyPressEvent(event);
}

void VtkViewportWidget::keyReleaseEvent(QKeyEvent* event) {
  const QPointF cursor = mapFromGlobal(QCursor::pos());
  setEventInformation(cursor, event->modifiers());
  interactor_->KeyReleaseEvent();
  QOpenGLWidget::keyReleaseEvent(event);
}

void VtkViewportWidget::enterEvent(QEnterEvent* event) {
  interactor_->EnterEvent();
  QOpenGLWidget::enterEvent(event);
}

void VtkViewportWidget::leaveEvent(QEvent* event) {
  interactor_->LeaveEvent();
  QOpenGLWidget::leaveEvent(event);
}

}  // namespace mq::ui
