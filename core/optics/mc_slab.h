#pragma once
// Monte-Carlo random walk in a layered slab, Hanrahan and Krueger's method
// (survey §1.5.1, "Résolution par marche aléatoire"), the reference the
// closed-form models are tested against. A photon with position, direction
// and unit weight enters at the origin; free paths are exponential in
// sigma_t, each collision scatters with probability W = sigma_s / sigma_t
// (new direction from Henyey-Greenstein) and absorbs the photon otherwise
// (analog absorption, so every result is a count of photons). Boundaries
// between different indices reflect or refract by the unpolarised Fresnel
// reflectance, so light is trapped by total internal reflection as in skin.
//
// Depth z grows downwards from the top surface z = 0; layer 0 is on top.
// Paths are traced in fixed blocks, each with its own seed derived from the
// settings' seed, and the counts are summed: the result is the same for any
// number of threads.

#include <cstdint>
#include <vector>

namespace mq::optics {

struct SlabLayer {
  double sigmaA = 0, sigmaS = 0;  // mm^-1
  double g = 0;                   // Henyey-Greenstein anisotropy
  double thickness = 1.0;         // mm; infinity for a half-space
  double index = 1.0;             // refractive index
};

struct SlabSettings {
  std::uint64_t seed = 1;
  std::int64_t paths = 200000;
  int threads = 2;
  double indexAbove = 1.0, indexBelow = 1.0;
  bool diffuseIncidence = false;  // cosine-distributed from above, else collimated
  double cosIncidence = 1.0;      // collimated beam's cos(theta) (in the plane xz)
  double annulusWidth = 0.1;      // mm
  int annulusCount = 64;
  int angularBins = 20;                      // single-scatter exits, uniform in cos(theta) outside
  int maxOrder = 64;                         // order histogram size; the last bin holds >= maxOrder
  std::int64_t maxEventsPerPath = 10000000;  // a path still inside then is "abandoned"
};

struct SlabResult {
  std::int64_t paths = 0;
  std::int64_t specular = 0;     // reflected at the entry surface
  std::int64_t reflected = 0;    // left through the top after entering
  std::int64_t transmitted = 0;  // left through the bottom
  std::int64_t absorbed = 0;
  std::int64_t abandoned = 0;
  std::vector<std::int64_t> annuli;             // reflected, by exit radius
  std::vector<std::int64_t> singleScatterBins;  // reflected after one event, by exit cos(theta)
  std::vector<std::int64_t> orders;             // reflected, by number of scattering events

  double reflectance() const { return double(reflected) / paths; }
  // Reflected per photon that entered: what the dipole's R_d predicts,
  // since it leaves the entry Fresnel factor to the caller.
  double reflectanceOfEntered() const { return double(reflected) / double(paths - specular); }
  double transmittance() const { return double(transmitted) / paths; }
  double singleScatterFraction() const { return orders.size() > 1 ? double(orders[1]) / paths : 0.0; }
};

SlabResult simulateSlab(const std::vector<SlabLayer>& layers, const SlabSettings& settings);

}  // namespace mq::optics
