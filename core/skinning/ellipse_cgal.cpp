// The CGAL part of ellipse.h (Min_ellipse_2 with exact rationals), in its own
// translation unit: slow to compile, and CGAL's flags stay here.
#include <CGAL/Cartesian.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Min_ellipse_2.h>
#include <CGAL/Min_ellipse_2_traits_2.h>

#include <algorithm>

#include "core/skinning/ellipse.h"

namespace mq {
namespace {

// Enough points to pin a section loop's enclosing ellipse; exact arithmetic
// grows with the support set, not with the points, but each point is tested.
constexpr size_t kMaxPoints = 96;

}  // namespace

Ellipse2 enclosingEllipse(const std::vector<glm::dvec2>& points) {
  using Kernel = CGAL::Cartesian<CGAL::Exact_rational>;
  using Traits = CGAL::Min_ellipse_2_traits_2<Kernel>;
  using MinEllipse = CGAL::Min_ellipse_2<Traits>;
  if (points.size() < 3) return {};
  const size_t stride = (points.size() + kMaxPoints - 1) / kMaxPoints;
  std::vector<Kernel::Point_2> sample;
  for (size_t i = 0; i < points.size(); i += stride) sample.emplace_back(points[i].x, points[i].y);
  const MinEllipse me(sample.begin(), sample.end(), true);
  if (me.is_degenerate()) return {};
  double r, s, t, u, v, w;
  me.ellipse().double_coefficients(r, s, t, u, v, w);
  Ellipse2 e = ellipseFromConic(r, s, t, u, v, w);
  if (!e.valid()) return e;
  // Grow it to cover the points the subsample skipped.
  double grow = 1.0;
  for (const glm::dvec2& p : points) {
    const glm::dvec2 d = p - e.center;
    const double len = glm::length(d);
    if (len > 0.0) grow = std::max(grow, len / e.radius(d / len));
  }
  e.a *= grow;
  e.b *= grow;
  return e;
}

}  // namespace mq
