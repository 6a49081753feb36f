#pragma once
// A QOpenGLWidget that hosts a vtkGenericOpenGLRenderWindow: VTK renders into
// its own framebuffer inside Qt's GL context, then we blit into the widget's
// framebuffer. Qt mouse, wheel and key events go to a
// vtkGenericRenderWindowInteractor with a DCC-style camera (orbit/pan/zoom).
// (Debian's VTK 9.1 ships QVTKOpenGLNativeWidget for Qt 5 only; replace this
// class with VTK's own when the platform has VTK >= 9.2.)

#include <QOpenGLWidget>

#include <vtkSmartPointer.h>

class vtkGenericOpenGLRenderWindow;
class vtkGenericRenderWindowInteractor;
class vtkInteractorObserver;
class vtkObject;
class vtkProp;
class vtkRenderer;

namespace mq::ui {

class VtkViewportWidget : public QOpenGLWidget {
  Q_OBJECT

 public:
  explicit VtkViewportWidget(QWidget* parent = nullptr);
  ~VtkViewportWidget() override;

  // The surface format the bridge needs; set it as the default before
  // QApplication is created (OpenGL 3.2 core, depth 24, stencil 8, no MSAA).
  static QSurfaceFormat defaultFormat();

  vtkGenericOpenGLRenderWindow* renderWindow() const;
  vtkGenericRenderWindowInteractor* interactor() const;
  // Adds a renderer to the window (the scene's, usually).
  void addRenderer(vtkRenderer* renderer);
  // Schedules a repaint; the only way the scene should be redrawn.
  void requestRender();
  // Schedules a paint that draws `prop` alone over the last frame (nothing
  // erased, the other props of the scene's layer hidden), after the events
  // waiting, unless a full frame is asked for first: for a prop that draws
  // itself in parts over several frames (the hair, see render::HairActor).
  void requestContinuation(vtkProp* prop);
  // The last rendered image (renders first if needed).

 signals:
  // Emitted after each frame has been drawn.
  void frameRendered();

 protected:
  void initializeGL() override;
  void resizeGL(int w, int h) override;
  void paintGL() override;

  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void mouseDoubleClickEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void keyPressEvent(QKeyEvent* event) override;
  void keyReleaseEvent(QKeyEvent* event) override;
  void enterEvent(QEnterEvent* event) override;
  void leaveEvent(QEvent* event) override;

 private:
  void connectWindowCallbacks();
  void onWindowEvent(vtkObject* caller, unsigned long eventId, void* callData);
  void clearAlpha();
  void renderContinuation(vtkProp* prop);
  // Sends modifiers and the position (device pixels, y up) to the interactor.
  void setEventInformation(const QPointF& position, Qt::KeyboardModifiers modifiers, int repeat = 0);

  vtkSmartPointer<vtkGenericOpenGLRenderWindow> renderWindow_;
  vtkSmartPointer<vtkGenericRenderWindowInteractor> interactor_;
  vtkSmartPointer<vtkInteractorObserver> cameraStyle_;
  bool glInitialized_ = false;
  bool fullFramePending_ = true;  // VTK's framebuffer does not hold the current scene
  vtkProp* continuation_ = nullptr;
};

}  // namespace mq::ui
