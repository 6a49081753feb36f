#include "ui/viewport/viewport_geometry.h"

#include <QWidget>

#include <vtkRenderer.h>

namespace mq::ui {

QPoint widgetToDisplay(const QWidget* viewport, const QPointF& position) {
  const qreal ratio = viewport->devicePixelRatioF();
  const int height = int(viewport->height() * ratio);
  return QPoint(int(position.x() * ratio), height - 1 - int(position.y() * ratio));
}

glm::vec2 worldToDisplay(vtkRenderer* renderer, const glm::vec3& world) {
  renderer->SetWorldPoint(world.x, world.y, world.z, 1.0);
  renderer->WorldToDisplay();
  const double* d = renderer->GetDisplayPoint();
  return {float(d[0]), float(d[1])};
}

ViewRay displayRay(vtkRenderer* renderer, const QPoint& display) {
  auto unproject = [&](double depth) {
    renderer->SetDisplayPoint(display.x(), display.y(), depth);
    renderer->DisplayToWorld();
    const double* w = renderer->GetWorldPoint();
    return glm::dvec3(w[0], w[1], w[2]) / (w[3] != 0.0 ? w[3] : 1.0);
  };
  const glm::dvec3 nearPoint = unproject(0.0), farPoint = unproject(1.0);
  ViewRay ray;
  ray.origin = glm::vec3(nearPoint);
  ray.direction = glm::vec3(glm::normalize(farPoint - nearPoint));
  return ray;
}

}  // namespace mq::ui
