#pragma once
// Fabric materials: the parameters the cloth solver needs, in SI units, and
// presets whose values come from published Kawabata (KES-F) measurements.
//
// KES units and their conversion (1 gf = 9.80665e-3 N):
//   bending rigidity B   [gf cm^2/cm] * 9.80665e-5 -> N m   (moment per width per curvature)
//   shear stiffness  G   [gf/cm/deg]  * 56.19      -> N/m per radian
//   extensibility  EMT   [% at 500 gf/cm]: stretch = 490.3 N/m / (EMT / 100)  (secant modulus)
//   weight           W   [mg/cm^2]    * 0.01       -> kg/m^2
//   thickness       T0   [mm]         * 1e-3       -> m

#include <string>
#include <vector>

namespace mq {

struct Fabric {
  std::string name = "custom";
  float massPerArea = 0.15f;        // kg/m^2
  float stretchStiffness = 1.0e4f;  // N/m: membrane tension per unit strain
  float shearStiffness = 50.0f;     // N/m per radian of in-plane shear
  float bendStiffness = 1.0e-5f;    // N m: bending moment per unit width per unit curvature
  float damping = 1e-3f;            // s: spring damping = damping * stiffness (Rayleigh)
  float friction = 0.3f;            // Coulomb coefficient against bodies and itself
  float thickness = 0.5e-3f;        // m

  // Throws mq::Error naming the first parameter that is not finite or out of range.
  void validate() const;
};

// KES conversions (see the table above).
float kesBendingToSi(float gfCm2PerCm);
float kesShearToSi(float gfPerCmDeg);
float kesExtensibilityToStretch(float emtPercent);

std::vector<std::string> fabricPresetNames();  // cotton, silk, denim, wool, leather
bool hasFabricPreset(const std::string& name);
// Throws mq::Error for an unknown name.
Fabric fabricPreset(const std::string& name);

}  // namespace mq
