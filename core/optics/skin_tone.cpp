#include "core/optics/skin_tone.h"

#include <cmath>

#include "core/optics/burley.h"
#include "core/optics/dipole.h"
#include "core/optics/kubelka_munk.h"
#include "core/util/error.h"

namespace mq::optics {

namespace {

constexpr Rgb kWavelengthNm = {650.0, 550.0, 450.0};
// Kubelka-Munk S of the epidermis per unit sigma_s', calibrated against mc_slab (header).
constexpr double kEpidermisScatteringToS = 0.16;

// Jensen et al. 2001, table of measured coefficients (mm^-1), eta 1.3.
constexpr Rgb kSkin1SigmaSPrime = {0.74, 0.88, 1.01};
constexpr Rgb kSkin1SigmaA = {0.032, 0.17, 0.48};
constexpr Rgb kSkin2SigmaSPrime = {1.09, 1.59, 1.79};
constexpr Rgb kSkin2SigmaA = {0.013, 0.070, 0.145};

double eumelaninAbsorption(double lambda) { return 6.6e10 * std::pow(lambda, -3.33); }
double pheomelaninAbsorption(double lambda) { return 2.9e14 * std::pow(lambda, -4.75); }
double baselineAbsorption(double lambda) { return 0.0244 + 8.53 * std::exp(-(lambda - 154.0) / 66.2); }
double epidermisScattering(double lambda) { return 14.74 * std::pow(lambda, -0.22) + 2.2e11 * std::pow(lambda, -4.0); }

// Whole blood (150 g/L hemoglobin, 64500 g/mol), 75 % oxygenated, mm^-1.
// Molar extinction (cm^-1 / M) of HbO2 and Hb at 650, 550, 450 nm: Prahl's
// tables as commonly quoted [unverified].
double bloodAbsorption(int channel) {
  constexpr Rgb oxy = {368.0, 43016.0, 62816.0};
  constexpr Rgb deoxy = {3750.8, 53412.0, 103292.0};
  constexpr double oxygenation = 0.75, molarity = 150.0 / 64500.0;
  const double extinction = oxygenation * oxy[channel] + (1.0 - oxygenation) * deoxy[channel];
  return std::log(10.0) * extinction * molarity / 10.0;  // cm^-1 -> mm^-1
}

SkinOptics measuredSkin(const std::string& name, const Rgb& sigmaA, const Rgb& sigmaSPrime) {
  return {name, sigmaA, sigmaSPrime, 1.3, true};
}

struct TonePreset {
  const char* name;
  double melanin;
};
// Melanosome fractions spread over the 1.3 %-43 % range Jacques gives
// (quoted second-hand, unverified); their colours come from skinFromTone.
constexpr TonePreset kTonePresets[] = {{"light", 0.02}, {"medium", 0.08}, {"tan", 0.16}, {"dark", 0.32}};

}  // namespace

Rgb SkinOptics::reducedAlbedo() const {
  Rgb out;
  for (int c = 0; c < 3; ++c) out[c] = Dipole(sigmaA[c], sigmaSPrime[c], eta).reducedAlbedo();
  return out;
}

Rgb SkinOptics::totalReflectance() const {
  Rgb out;
  for (int c = 0; c < 3; ++c) out[c] = Dipole(sigmaA[c], sigmaSPrime[c], eta).totalReflectance();
  return out;
}

Rgb SkinOptics::diffuseMeanFreePath() const {
  Rgb out;
  for (int c = 0; c < 3; ++c) out[c] = Dipole(sigmaA[c], sigmaSPrime[c], eta).diffuseMeanFreePath();
  return out;
}

SkinLayers skinLayers(const SkinTone& tone) {
  SkinLayers layers;
  layers.epidermisThickness = tone.epidermisThickness;
  layers.eta = tone.eta;
  for (int c = 0; c < 3; ++c) {
    const double lambda = kWavelengthNm[c];
    const double melaninMix = tone.eumelaninFraction * eumelaninAbsorption(lambda) +
                              (1.0 - tone.eumelaninFraction) * pheomelaninAbsorption(lambda);
    layers.epidermisSigmaA[c] = tone.melanin * melaninMix + (1.0 - tone.melanin) * baselineAbsorption(lambda);
    layers.epidermisSigmaSPrime[c] = epidermisScattering(lambda);
    layers.dermisSigmaA[c] =
        tone.hemoglobin * bloodAbsorption(c) + (1.0 - tone.hemoglobin) * baselineAbsorption(lambda);
    layers.dermisSigmaSPrime[c] = kSkin1SigmaSPrime[c];
  }
  return layers;
}

SkinOptics skinFromTone(const SkinTone& tone, const std::string& name) {
  const SkinLayers layers = skinLayers(tone);
  SkinOptics skin{name, {}, {}, tone.eta, false};
  for (int c = 0; c < 3; ++c) {
    const KubelkaMunkLayer epidermis =
        kubelkaMunkLayer(2.0 * layers.epidermisSigmaA[c], kEpidermisScatteringToS * layers.epidermisSigmaSPrime[c],
                         layers.epidermisThickness);
    const Dipole dermis(layers.dermisSigmaA[c], layers.dermisSigmaSPrime[c], tone.eta);
    const KubelkaMunkLayer dermisHalfSpace{dermis.totalReflectance(), 0.0, dermis.totalReflectance()};
    const double reflectance = addLayers(epidermis, dermisHalfSpace).reflectance;
    const ReducedCoefficients effective =
        coefficientsFromReflectance(reflectance, dermis.diffuseMeanFreePath(), tone.eta);
    skin.sigmaA[c] = effective.sigmaA;
    skin.sigmaSPrime[c] = effective.sigmaSPrime;
  }
  return skin;
}

std::vector<std::string> skinPresetNames() {
  std::vector<std::string> names = {"skin1", "skin2"};
  for (const TonePreset& preset : kTonePresets) names.push_back(preset.name);
  return names;
}

SkinOptics skinPreset(const std::string& name) {
  if (name == "skin1") return measuredSkin(name, kSkin1SigmaA, kSkin1SigmaSPrime);
  if (name == "skin2") return measuredSkin(name, kSkin2SigmaA, kSkin2SigmaSPrime);
  for (const TonePreset& preset : kTonePresets)
    if (name == preset.name) {
      SkinTone tone;
      tone.melanin = preset.melanin;
      return skinFromTone(tone, name);
    }
  std::string choices;
  for (const std::string& known : skinPresetNames()) choices += (choices.empty() ? "" : ", ") + known;
  throw Error("unknown skin preset '" + name + "' (expected " + choices + ")");
}

BlenderSubsurface blenderEquivalent(const SkinOptics& skin) {
  BlenderSubsurface blender;
  blender.baseColor = blender.subsurfaceColor = skin.totalReflectance();
  blender.subsurfaceRadius = skin.diffuseMeanFreePath();
  blender.subsurfaceIor = skin.eta;
  return blender;
}

std::array<LineSpreadKernel, 3> skinKernels(const SkinOptics& skin) {
  const Rgb reflectance = skin.totalReflectance(), meanFreePath = skin.diffuseMeanFreePath();
  std::array<LineSpreadKernel, 3> kernels;
  for (int c = 0; c < 3; ++c)
    kernels[c] = skin.measured ? dipoleKernel(Dipole(skin.sigmaA[c], skin.sigmaSPrime[c], skin.eta))
                               : burleyKernel(burleyFromDiffuseMfp(reflectance[c], meanFreePath[c]));
  return kernels;
}

}  // namespace mq::optics
