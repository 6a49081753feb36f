#pragma once
// Skin colour from its chromophores, per RGB channel (survey §1.3.1, "Modèle
// d'éclairage": two quasi-homogeneous layers with one refractive index, the
// epidermis coloured by melanin, the dermis by blood; §1.5.1's two-layer
// table; §1.5.2's "W = 0.95, g = 0.85"). The survey gives no coefficients;
// they come from:
//
// - Jensen et al. 2001, measured skin ("skin1", "skin2"): sigma_a and
//   sigma_s' per channel, eta = 1.3. Used as given, one layer.
// - Tone model, two layers (Donner and Jensen 2006 spectral forms, lambda in
//   nm, mm^-1), evaluated at one wavelength per channel (650, 550, 450 nm), a
//   simplification of integrating spectra against the RGB primaries:
//     epidermis sigma_a = C_m (beta_m 6.6e10 lambda^-3.33 + (1 - beta_m) 2.9e14 lambda^-4.75)
//                         + (1 - C_m) baseline,
//               baseline = 0.0244 + 8.53 e^{-(lambda - 154)/66.2},
//     epidermis sigma_s' = 14.74 lambda^-0.22 + 2.2e11 lambda^-4,
//     dermis    sigma_a = C_h blood(lambda) + (1 - C_h) baseline, blood 75 % oxygenated,
//     dermis    sigma_s' = Jensen's measured skin1 sigma_s' (a measured dermis-dominated value).
//   The epidermis (0.1 mm) is a Kubelka-Munk layer with K = 2 sigma_a and
//   S = 0.16 sigma_s'; the dermis is a dipole half-space; the two combine by
//   the Kubelka-Munk adding rule. K = 2 sigma_a is the usual diffuse
//   path-length factor; the 0.16 was calibrated against mc_slab (the same two
//   layers, diffuse incidence, eta 1.4, g 0.79 and 0.81, C_m 0.01-0.43,
//   reflectance per photon entered like the dipole's R_d): the closed form is
//   then within about 9 % (rms of the log) of the random walk, where 0.75
//   (diffusion theory's 3/4) is off by a factor 2-3.
//   That reference also shows the limit of "more melanin, less blue": B/R
//   falls until C_m is about 0.2, then rises again as the epidermis' own
//   backscatter, which melanin cannot absorb before it leaves, dominates.
//   The result is reported as one effective
//   layer: its total reflectance R_d, the dermis' diffuse mean free path
//   1/sigma_tr, and the sigma_a, sigma_s' of a dipole with those two values.
//   Unverified inputs: the hemoglobin extinction values (Prahl's tables as
//   commonly quoted, not re-read) and the 650/550/450 nm choice.

#include <array>
#include <string>
#include <vector>

#include "core/optics/preintegrated.h"

namespace mq::optics {

using Rgb = std::array<double, 3>;

struct SkinOptics {
  std::string name;
  Rgb sigmaA{}, sigmaSPrime{};  // mm^-1
  double eta = 1.3;
  bool measured = false;  // Jensen's measured coefficients, not the tone model

  Rgb reducedAlbedo() const;
  Rgb totalReflectance() const;     // dipole R_d
  Rgb diffuseMeanFreePath() const;  // 1 / sigma_tr, mm
};

struct SkinTone {
  double melanin = 0.05;            // C_m, volume fraction of melanosomes in the epidermis
  double eumelaninFraction = 0.7;   // beta_m, eumelanin / (eu + pheo)
  double hemoglobin = 0.01;         // C_h, volume fraction of blood in the dermis
  double epidermisThickness = 0.1;  // mm
  double eta = 1.4;
};

// The tone model's two layers, per channel (mm^-1): what skinFromTone
// combines, and what mc_slab can trace as the reference.
struct SkinLayers {
  Rgb epidermisSigmaA{}, epidermisSigmaSPrime{}, dermisSigmaA{}, dermisSigmaSPrime{};
  double epidermisThickness = 0, eta = 0;
};
SkinLayers skinLayers(const SkinTone& tone);

SkinOptics skinFromTone(const SkinTone& tone, const std::string& name = "tone");

// "skin1", "skin2" (Jensen 2001) and tone presets "light", "medium", "tan",
// "dark" (skinFromTone with the melanin fractions in skin_tone.cpp). Throws
// mq::Error naming the choices for an unknown name.
SkinOptics skinPreset(const std::string& name);
std::vector<std::string> skinPresetNames();

// Blender Principled BSDF settings for the same skin: base and subsurface
// colour = R_d (linear); radius = diffuse mean free path 1/sigma_tr in mm;
// IOR = eta. In a scene in metres, Blender 4 takes Subsurface Weight 1,
// Radius in mm and Subsurface Scale 0.001; Blender 3's Subsurface factor both
// weights and scales the radius, so there Subsurface = 1 and Radius =
// radius * 0.001 (metres).
struct BlenderSubsurface {
  Rgb baseColor{}, subsurfaceColor{}, subsurfaceRadius{};
  double subsurfaceScale = 0.001, subsurfaceWeight = 1.0, subsurfaceIor = 1.4;
};
BlenderSubsurface blenderEquivalent(const SkinOptics& skin);

// The line-spread kernels the pre-integrated LUT should use for this skin:
// the dipole for measured presets, Burley (R_d, diffuse mean free path) for
// the tone model.
std::array<LineSpreadKernel, 3> skinKernels(const SkinOptics& skin);

}  // namespace mq::optics
