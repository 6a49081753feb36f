#pragma once
// What every GUI test needs: the editor window it drives (an error dialog
// fails the test, discarding changes is always allowed, the size is fixed so
// picks and drags land in the same places on every run; shown, wait for it to
// be exposed), synchronous painting, mouse events and world-to-widget points.

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <thread>

#include <vtkRenderer.h>
#include <QApplication>
#include <QDoubleSpinBox>
#include <QMouseEvent>
#include <QTest>
#include <glm/glm.hpp>

#include "render/scene_view.h"
#include "ui/main_window.h"
#include "ui/viewport/vtk_viewport_widget.h"

namespace mq::ui {

// A widget test must never hang, even when the event loop is stuck: the
// process gives up after `seconds`, saying so.
inline void exitAfter(int seconds, const char* testName) {
  std::thread([seconds, testName] {
    std::this_thread::sleep_for(std::chrono::seconds(seconds));
    std::fprintf(stderr, "%s: timed out\n", testName);
    std::_Exit(2);
  }).detach();
}

inline MainWindow* makeTestWindow() {
  auto* window = new MainWindow;
  window->reportError = [](const QString& title, const QString& message) {
    QFAIL(qPrintable("unexpected error dialog: " + title + ": " + message));
  };
  window->confirmDiscardChanges = [] { return true; };
  window->resize(1280, 800);
  window->show();
  return window;
}

// Paints the viewport now (grabbing the framebuffer renders synchronously).
inline void renderNow(MainWindow* window) {
  window->viewport()->grabFramebuffer();
  QApplication::processEvents();
}

// Sends a mouse event straight to the widget (event filters see it first,
// as with real input).
inline void sendMouse(QWidget* w, QEvent::Type type, QPoint pos, Qt::MouseButton button, Qt::MouseButtons buttons,
                      Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
  QMouseEvent event(type, QPointF(pos), w->mapToGlobal(QPointF(pos)), button, buttons, modifiers);
  QApplication::sendEvent(w, &event);
}

// Types `value` into a spin box and presses Enter, as a user does.
inline void typeValue(QDoubleSpinBox* box, double value) {
  box->selectAll();
  QTest::keyClicks(box, QString::number(value));
  QTest::keyClick(box, Qt::Key_Return);
}

// Widget coordinates of a world point in the viewport.
inline QPoint toWidget(MainWindow* window, const glm::vec3& world) {
  vtkRenderer* renderer = window->sceneView()->renderer();
  renderer->SetWorldPoint(world.x, world.y, world.z, 1.0);
  renderer->WorldToDisplay();
  const double* d = renderer->GetDisplayPoint();
  const double ratio = window->viewport()->devicePixelRatioF();
  return QPoint(int(d[0] / ratio), int((window->viewport()->height() * ratio - 1 - d[1]) / ratio));
}

}  // namespace mq::ui
