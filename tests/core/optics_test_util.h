#pragma once
// Quadrature helpers for the optics tests: independent of the code under test.
#include <cmath>
#include <functional>

namespace mq::optics::test {

// Composite Simpson on [a, b] with `intervals` (even) intervals.
inline double simpson(const std::function<double(double)>& f, double a, double b, int intervals) {
  const double h = (b - a) / intervals;
  double sum = f(a) + f(b);
  for (int k = 1; k < intervals; ++k) sum += (k % 2 ? 4.0 : 2.0) * f(a + k * h);
  return sum * h / 3.0;
}

// int_lo^hi f(r) dr on a log-spaced grid (r = e^u, dr = r du), Simpson in u.
inline double logSimpson(const std::function<double(double)>& f, double lo, double hi, int intervals) {
  return simpson(
      [&](double u) {
        const double r = std::exp(u);
        return f(r) * r;
      },
      std::log(lo), std::log(hi), intervals);
}

// Standard error of a fraction p estimated from n Bernoulli trials.
inline double standardError(double p, double n) { return std::sqrt(std::max(p * (1.0 - p), 1e-12) / n); }

}  // namespace mq::optics::test
