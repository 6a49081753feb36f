// mannequin-cli hair-color: the absorption of a hair fibre from its pigments
// (core/optics/hair_bsdf.h), per RGB channel, and the share of light such a
// fibre sends back (its mean albedo), for the physical hair shader.
#include <iomanip>
#include <iostream>

#include <nlohmann/json.hpp>

#include "app/cli/command.h"
#include "core/optics/hair_bsdf.h"
#include "core/util/error.h"

namespace mq::cli {
namespace {

int runHairColor(const std::vector<std::string>& argv) {
  const Args args(argv);
  args.allowOnly({"--melanin", "--pheomelanin", "--preset", "--roughness", "--json"});
  if (!args.positional().empty()) throw Error("hair-color takes no FILE; see mannequin-cli --help");
  optics::HairPigment pigment;
  if (args.has("--preset")) pigment = optics::hairPigmentPreset(args.option("--preset"));
  pigment.eumelanin = args.number("--melanin", pigment.eumelanin);
  pigment.pheomelanin = args.number("--pheomelanin", pigment.pheomelanin);
  if (pigment.eumelanin < 0.0 || pigment.pheomelanin < 0.0) throw Error("--melanin and --pheomelanin must be >= 0");
  optics::HairFibre fibre;
  fibre.sigmaA = optics::hairSigmaAFromPigment(pigment);
  fibre.longitudinalRoughness = fibre.azimuthalRoughness = args.number("--roughness", 0.3);
  if (!(fibre.longitudinalRoughness >= 0.05 && fibre.longitudinalRoughness <= 1.0))
    throw Error("--roughness must be in 0.05..1");
  const optics::Rgb albedo = optics::hairMeanAlbedo(fibre);
  if (args.has("--json")) {
    nlohmann::json out = {{"melanin", pigment.eumelanin},
                          {"pheomelanin", pigment.pheomelanin},
                          {"roughness", fibre.longitudinalRoughness},
                          {"sigma_a", fibre.sigmaA},
                          {"mean_albedo", albedo}};
    std::cout << std::setw(2) << out << "\n";
    return 0;
  }
  std::cout << std::fixed << std::setprecision(4) << "eumelanin " << pigment.eumelanin << ", pheomelanin "
            << pigment.pheomelanin << "\n"
            << "sigma_a (per fibre radius)  R " << fibre.sigmaA[0] << "  G " << fibre.sigmaA[1] << "  B "
            << fibre.sigmaA[2] << "\n"
            << "mean albedo (roughness " << std::setprecision(2) << fibre.longitudinalRoughness << ")  R "
            << std::setprecision(4) << albedo[0] << "  G " << albedo[1] << "  B " << albedo[2] << "\n";
  return 0;
}

Registration reg({"hair-color",
                  "[--preset black|brown|blond|red|grey] [--melanin M] [--pheomelanin P] [--roughness R] [--json]",
                  "hair absorption sigma_a per RGB channel from melanin concentrations (Chiang et al. 2016), "
                  "and the fibre's mean albedo",
                  runHairColor});

}  // namespace
}  // namespace mq::cli
