#pragma once
// Phase functions for scattering inside skin (survey §1.5.1, "Fonctions de
// phase", after Hanrahan and Krueger 1993). A phase function p(cos psi) is the
// probability density, per steradian, that light travelling along w scatters
// into w' with cos psi = w . w'; it integrates to 1 over the sphere.
//
//   Henyey-Greenstein:  p(psi) = (1 - g^2) / (4 pi (1 + g^2 - 2 g cos psi)^{3/2})
//   its mean cosine is g; g > 0 scatters forward (skin: g = 0.85).
//   Schlick (Blasi, Le Saec, Schlick 1993), a cheaper stand-in:
//                       p(psi) = (1 - k^2) / (4 pi (1 - k cos psi)^2),
//                       k = 1.55 g - 0.55 g^3.

namespace mq::optics {

double henyeyGreenstein(double cosPsi, double g);

// cos psi drawn from Henyey-Greenstein with a uniform xi in [0, 1):
//   cos psi = (1 + g^2 - ((1 - g^2) / (1 - g + 2 g xi))^2) / (2 g),
// and 2 xi - 1 (isotropic) when g is about 0, where that form cancels badly.
double sampleHenyeyGreenstein(double g, double xi);

double schlickK(double g);
double schlickPhase(double cosPsi, double g);

}  // namespace mq::optics
