// mannequin-cli skin (--preset NAME | --melanin M --hemoglobin H) [--json]:
// the optical coefficients of a skin (core/optics/skin_tone.h) per RGB
// channel, and the Blender Principled BSDF settings that match them.
#include <cstdio>
#include <iomanip>
#include <iostream>

#include <nlohmann/json.hpp>

#include "app/cli/command.h"
#include "core/optics/skin_tone.h"
#include "core/util/error.h"

namespace mq::cli {
namespace {

using optics::Rgb;

double fraction(const Args& args, const std::string& name) {
  const double value = args.number(name, -1.0);
  if (value < 0.0 || value > 1.0) throw Error(name + " expects a volume fraction in [0, 1]");
  return value;
}

optics::SkinOptics chooseSkin(const Args& args) {
  const bool preset = args.has("--preset"), tone = args.has("--melanin") || args.has("--hemoglobin");
  if (preset == tone) throw Error("skin needs either --preset NAME or --melanin M --hemoglobin H");
  if (preset) return optics::skinPreset(args.option("--preset"));
  if (!args.has("--melanin") || !args.has("--hemoglobin")) throw Error("skin needs both --melanin and --hemoglobin");
  optics::SkinTone skinTone;
  skinTone.melanin = fraction(args, "--melanin");
  skinTone.hemoglobin = fraction(args, "--hemoglobin");
  return optics::skinFromTone(skinTone);
}

Rgb scaled(const Rgb& v, double factor) { return {v[0] * factor, v[1] * factor, v[2] * factor}; }

nlohmann::json describe(const optics::SkinOptics& skin) {
  const optics::BlenderSubsurface blender = optics::blenderEquivalent(skin);
  return {{"name", skin.name},
          {"measured", skin.measured},
          {"sigma_a", skin.sigmaA},
          {"sigma_s_prime", skin.sigmaSPrime},
          {"eta", skin.eta},
          {"albedo", skin.reducedAlbedo()},
          {"rd", skin.totalReflectance()},
          {"mfp_mm", skin.diffuseMeanFreePath()},
          {"blender",
           {{"base_color", blender.baseColor},
            {"subsurface_weight", blender.subsurfaceWeight},
            {"subsurface_radius_mm", blender.subsurfaceRadius},
            {"subsurface_scale", blender.subsurfaceScale},
            {"subsurface_radius_m", scaled(blender.subsurfaceRadius, blender.subsurfaceScale)},
            {"subsurface_color", blender.subsurfaceColor},
            {"subsurface_ior", blender.subsurfaceIor}}}};
}

void printRow(std::ostream& out, const char* label, const Rgb& v, int precision) {
  out << "  " << std::left << std::setw(30) << label << std::right << std::fixed << std::setprecision(precision);
  for (double x : v) out << std::setw(10) << x;
  out << "\n";
}

void printText(const optics::SkinOptics& skin, std::ostream& out) {
  const optics::BlenderSubsurface blender = optics::blenderEquivalent(skin);
  out << skin.name << (skin.measured ? " (measured, Jensen et al. 2001)" : " (melanin and hemoglobin model)")
      << ", eta " << std::setprecision(3) << skin.eta << "\n";
  out << "  " << std::setw(30) << "" << std::setw(10) << "red" << std::setw(10) << "green" << std::setw(10) << "blue"
      << "\n";
  printRow(out, "sigma_a (1/mm)", skin.sigmaA, 4);
  printRow(out, "sigma_s' (1/mm)", skin.sigmaSPrime, 4);
  printRow(out, "reduced albedo", skin.reducedAlbedo(), 4);
  printRow(out, "diffuse reflectance R_d", skin.totalReflectance(), 4);
  printRow(out, "diffuse mean free path (mm)", skin.diffuseMeanFreePath(), 3);
  out << "Blender Principled BSDF (scene in metres):\n";
  printRow(out, "Base Color, Subsurface Color", blender.subsurfaceColor, 4);
  printRow(out, "Subsurface Radius (mm)", blender.subsurfaceRadius, 3);
  out << "  Blender 4: Subsurface Weight 1, Subsurface Scale " << std::setprecision(3) << blender.subsurfaceScale
      << "; Blender 3: Subsurface 1, Radius in metres:\n";
  printRow(out, "Subsurface Radius (m)", scaled(blender.subsurfaceRadius, blender.subsurfaceScale), 6);
  out << "  Subsurface IOR " << std::setprecision(2) << blender.subsurfaceIor << "\n";
}

int runSkin(const std::vector<std::string>& argv) {
  const Args args(argv);
  args.allowOnly({"--preset", "--melanin", "--hemoglobin", "--json"});
  if (!args.positional().empty()) throw Error("skin takes no FILE");
  const optics::SkinOptics skin = chooseSkin(args);
  if (args.has("--json"))
    std::cout << std::setw(2) << describe(skin) << "\n";
  else
    printText(skin, std::cout);
  return 0;
}

std::string presetList() {
  std::string list;
  for (const std::string& name : optics::skinPresetNames()) list += (list.empty() ? "" : ", ") + name;
  return list;
}

static Registration reg({"skin", "(--preset NAME | --melanin M --hemoglobin H) [--json]",
                         "skin optics per RGB channel: sigma_a, sigma_s', eta, reduced albedo, diffuse reflectance, "
                         "mean free path, and Blender Principled BSDF settings; presets: " +
                             presetList(),
                         runSkin});

}  // namespace
}  // namespace mq::cli
