#pragma once
// First-order (single) scattering of a layer, Hanrahan and Krueger 1993
// (survey §1.5.1, "Résolution pour la première dispersion"). The survey's
// typeset formula puts Seeliger's L_r,v inside the bracket; the corrected form
// (its semi-infinite part as in Mitsuba 0.5's hk BSDF) is, as a BRDF,
//
//   f_r(1) = W T12 T21 p(psi) / (cos t_i + cos t_r) (1 - e^{-tau_d (1/cos t_i + 1/cos t_r)})
//
// with W = sigma_s / sigma_t, tau_d = sigma_t d, t_i and t_r the refracted
// angles inside the layer, T12 and T21 the Fresnel transmittances in and out,
// and psi the angle between the refracted incident direction (going down) and
// the refracted direction that leaves towards the viewer (going up).

#include <glm/glm.hpp>

namespace mq::optics {

struct ScatteringLayer {
  double sigmaA = 0, sigmaS = 0;  // mm^-1
  double g = 0;                   // Henyey-Greenstein anisotropy
  double thickness = 1e30;        // mm; a huge value is a semi-infinite layer
  double eta = 1;                 // index of the layer over the index above it
};

// f_r(1) in sr^-1. toLight and toViewer are unit vectors away from the
// surface, whose normal is +z; both must have z > 0.
double hanrahanKruegerBrdf(const ScatteringLayer& layer, const glm::dvec3& toLight, const glm::dvec3& toViewer);

}  // namespace mq::optics
