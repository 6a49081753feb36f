#include "core/skinning/ellipse.h"

#include <cmath>

namespace mq {

double Ellipse2::radius(const glm::dvec2& d) const {
  const double along = glm::dot(d, major);
  const double across = d.x * -major.y + d.y * major.x;
  return 1.0 / std::sqrt(along * along / (a * a) + across * across / (b * b));
}

namespace {

// Unit eigenvector of the larger eigenvalue of [[xx, xy], [xy, yy]], and both eigenvalues.
void symmetricEigen(double xx, double xy, double yy, glm::dvec2& major, double& large, double& small) {
  const double mean = 0.5 * (xx + yy);
  const double spread = std::sqrt(0.25 * (xx - yy) * (xx - yy) + xy * xy);
  large = mean + spread;
  small = mean - spread;
  const double angle = 0.5 * std::atan2(2.0 * xy, xx - yy);
  major = {std::cos(angle), std::sin(angle)};
}

}  // namespace

Ellipse2 momentEllipse(const std::vector<glm::dvec2>& polygon) {
  // Green's theorem: area, first and second moments of the enclosed region.
  double area = 0.0, cx = 0.0, cy = 0.0, ixx = 0.0, iyy = 0.0, ixy = 0.0;
  for (size_t i = 0, n = polygon.size(); i < n; ++i) {
    const glm::dvec2& p = polygon[i];
    const glm::dvec2& q = polygon[(i + 1) % n];
    const double cross = p.x * q.y - q.x * p.y;
    area += cross;
    cx += (p.x + q.x) * cross;
    cy += (p.y + q.y) * cross;
    ixx += (p.x * p.x + p.x * q.x + q.x * q.x) * cross;
    iyy += (p.y * p.y + p.y * q.y + q.y * q.y) * cross;
    ixy += (p.x * q.y + 2.0 * p.x * p.y + 2.0 * q.x * q.y + q.x * p.y) * cross;
  }
  Ellipse2 e;
  if (std::abs(area) < 1e-300) return e;
  area *= 0.5;
  cx /= 6.0 * area;
  cy /= 6.0 * area;
  // Central second moments per unit area (the signs cancel with the area's).
  const double mxx = ixx / 12.0 / area - cx * cx;
  const double myy = iyy / 12.0 / area - cy * cy;
  const double mxy = ixy / 24.0 / area - cx * cy;
  double large = 0.0, small = 0.0;
  symmetricEigen(mxx, mxy, myy, e.major, large, small);
  if (!(small > 0.0)) return e;
  // A filled ellipse has second moments a^2/4 and b^2/4 per unit area; then
  // scale so that pi a b is the section's area.
  e.center = {cx, cy};
  e.a = 2.0 * std::sqrt(large);
  e.b = 2.0 * std::sqrt(small);
  const double k = std::sqrt(std::abs(area) / (M_PI * e.a * e.b));
  e.a *= k;
  e.b *= k;
  return e;
}

Ellipse2 ellipseFromConic(double r, double s, double t, double u, double v, double w) {
  Ellipse2 e;
  const double det = r * s - 0.25 * t * t;
  if (!(det > 0.0)) return e;
  // Centre: the gradient vanishes, [[2r, t], [t, 2s]] c = -(u, v).
  const double cx = (-u * 2.0 * s + v * t) / (4.0 * det);
  const double cy = (-v * 2.0 * r + u * t) / (4.0 * det);
  const double value = r * cx * cx + s * cy * cy + t * cx * cy + u * cx + v * cy + w;
  double large = 0.0, small = 0.0;
  glm::dvec2 major;
  symmetricEigen(r, 0.5 * t, s, major, large, small);
  // (x - c)^T A (x - c) = -value: the semi-axis along A's eigenvector of
  // eigenvalue l is sqrt(-value / l) (the conic may come with either sign).
  const double alongMajor = -value / large, alongMinor = -value / small;
  if (!(alongMajor > 0.0 && alongMinor > 0.0)) return e;
  e.center = {cx, cy};
  e.a = std::sqrt(alongMajor);
  e.b = std::sqrt(alongMinor);
  e.major = major;
  if (e.a < e.b) std::swap(e.a, e.b), e.major = {-major.y, major.x};
  return e;
}

}  // namespace mq
