#pragma once
// Ellipses in a plane chart, as the section cones use them: centre, unit
// major direction and semi-axes. radius(d) is the distance from the centre to
// the ellipse along the unit direction d.

#include <vector>

#include <glm/glm.hpp>

namespace mq {

struct Ellipse2 {
  glm::dvec2 center{0.0};
  glm::dvec2 major{1.0, 0.0};  // unit
  double a = 0.0, b = 0.0;     // semi-axes along major and its perpendicular

  double radius(const glm::dvec2& unitDirection) const;
  bool valid() const { return a > 0.0 && b > 0.0; }
};

// The ellipse with the polygon's area, centroid and second moments (the
// "memorised section surface" of the survey's cones).
Ellipse2 momentEllipse(const std::vector<glm::dvec2>& polygon);

// The smallest ellipse enclosing the points (CGAL's Min_ellipse_2 on a
// subsample, then grown to cover every point). Invalid for fewer than three
// points in general position.
Ellipse2 enclosingEllipse(const std::vector<glm::dvec2>& points);

// The ellipse of the conic r x^2 + s y^2 + t xy + u x + v y + w = 0;
// invalid when the conic is not a real ellipse.
Ellipse2 ellipseFromConic(double r, double s, double t, double u, double v, double w);

}  // namespace mq
