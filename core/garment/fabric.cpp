#include "core/garment/fabric.h"

#include <cmath>

#include "core/util/error.h"

namespace mq {

namespace {

constexpr float kGramForce = 9.80665e-3f;  // N
constexpr float kPi = 3.14159265358979f;

Fabric makeFabric(const char* name, float weightMgPerCm2, float emtPercent, float shearG, float bendingB,
                  float thicknessMm, float friction) {
  Fabric f;
  f.name = name;
  f.massPerArea = weightMgPerCm2 * 0.01f;
  f.stretchStiffness = kesExtensibilityToStretch(emtPercent);
  f.shearStiffness = kesShearToSi(shearG);
  f.bendStiffness = kesBendingToSi(bendingB);
  f.thickness = thicknessMm * 1e-3f;
  f.friction = friction;
  return f;
}

// Sources of the preset values (KES-F: W, EMT, G, B, T0; MIU for friction):
//
// denim: "Regenerated Cellulose-Based Denim Fabric for Tropical Regions: An
//   Analytical Study on Making Denim Comfortable", Journal of Textiles (Hindawi)
//   2016, article 4614168, Table 5, fabric A (cotton denim): EMT 5.52 %,
//   B 0.172 gf cm^2/cm, G 2.18 gf/cm/deg, T 1.07 mm. That table's weight and
//   MIU columns are not usable (104 mg/cm^2, MIU 1.77 are not plausible for
//   denim), so the weight is the trade's 12 oz/yd^2 denim (40.7 mg/cm^2) and
//   the friction a typical cotton-on-skin value.
// cotton (plain-weave shirting), wool (worsted suiting), silk (crepe de chine):
//   values inside the ranges Kawabata and Niwa give for these fabric classes
//   ("Fabric performance in clothing and clothing manufacture", J. Textile
//   Institute 80(1), 1989, 19-50) and that Breen, House and Wozny used for
//   their KES-driven drape model (Textile Research Journal 64(11), 1994).
//   Representative values, not one measured sample: cotton W 12, EMT 4.0,
//   G 1.0, B 0.08, T 0.35; wool W 20, EMT 6.0, G 0.6, B 0.10, T 0.70;
//   silk W 6, EMT 5.0, G 0.35, B 0.025, T 0.15.
// leather (garment nappa, ~0.9 mm): KES-F has been applied to garment leather
//   (e.g. Alley, J. Society of Leather Technologists and Chemists, 1990s),
//   which is far stiffer in bending and shear than woven fabrics and more
//   extensible; the values here (W 65, EMT 12, G 8, B 1.5, T 0.9) are an
//   order-of-magnitude estimate in that spirit, the least certain preset.
Fabric presetByName(const std::string& name) {
  if (name == "cotton") return makeFabric("cotton", 12.0f, 4.0f, 1.0f, 0.08f, 0.35f, 0.3f);
  if (name == "silk") return makeFabric("silk", 6.0f, 5.0f, 0.35f, 0.025f, 0.15f, 0.2f);
  if (name == "denim") return makeFabric("denim", 40.7f, 5.52f, 2.18f, 0.172f, 1.07f, 0.4f);
  if (name == "wool") return makeFabric("wool", 20.0f, 6.0f, 0.6f, 0.10f, 0.70f, 0.35f);
  if (name == "leather") return makeFabric("leather", 65.0f, 12.0f, 8.0f, 1.5f, 0.9f, 0.5f);
  throw Error("unknown fabric preset '" + name + "' (known: cotton, silk, denim, wool, leather)");
}

void requirePositive(const char* what, float value) {
  if (!std::isfinite(value) || value <= 0.0f)
    throw Error(std::string("fabric parameter ") + what + " must be a positive number");
}

void requireNonNegative(const char* what, float value) {
  if (!std::isfinite(value) || value < 0.0f)
    throw Error(std::string("fabric parameter ") + what + " must be a non-negative number");
}

}  // namespace

float kesBendingToSi(float gfCm2PerCm) { return gfCm2PerCm * kGramForce * 1e-2f; }
float kesShearToSi(float gfPerCmDeg) { return gfPerCmDeg * kGramForce / 1e-2f * (180.0f / kPi); }
float kesExtensibilityToStretch(float emtPercent) { return 500.0f * kGramForce / 1e-2f / (emtPercent / 100.0f); }

void Fabric::validate() const {
  requirePositive("mass_per_area", massPerArea);
  requirePositive("stretch", stretchStiffness);
  requireNonNegative("shear", shearStiffness);
  requireNonNegative("bend", bendStiffness);
  requireNonNegative("damping", damping);
  requireNonNegative("friction", friction);
  requireNonNegative("thickness", thickness);
}

std::vector<std::string> fabricPresetNames() { return {"cotton", "silk", "denim", "wool", "leather"}; }

bool hasFabricPreset(const std::string& name) {
  for (const auto& n : fabricPresetNames())
    if (n == name) return true;
  return false;
}

Fabric fabricPreset(const std::string& name) { return presetByName(name); }

}  // namespace mq
