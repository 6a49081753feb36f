#pragma once
// Points and rays between the viewport widget, VTK's display coordinates
// (device pixels, origin bottom left) and the world, for the tools that pick
// and drag in the viewport (the pose tool, the collider drag tool).

#include <QPoint>
#include <QPointF>

#include <glm/glm.hpp>

class QWidget;
class vtkRenderer;

namespace mq::ui {

// A press and release closer than this (Manhattan, widget pixels) is a click.
constexpr int kClickTolerancePixels = 4;

// Display coordinates of a position in `viewport` (widget coordinates).
QPoint widgetToDisplay(const QWidget* viewport, const QPointF& position);
// Display coordinates (pixels, fractional) of a world point.
glm::vec2 worldToDisplay(vtkRenderer* renderer, const glm::vec3& world);

struct ViewRay {
  glm::vec3 origin{0.0f};     // on the near plane
  glm::vec3 direction{0.0f};  // unit, away from the viewer
};
// The line of sight through a display point.
ViewRay displayRay(vtkRenderer* renderer, const QPoint& display);

}  // namespace mq::ui
