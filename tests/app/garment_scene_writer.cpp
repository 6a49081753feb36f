// mannequin_garment_scene CHARACTER TYPE CLIP OUT.json [NAME=VALUE ...]:
// writes a scene document that plays CLIP (rest: none) on CHARACTER ("default" or a
// character file) wearing the built-in garment TYPE made for it
// (makeParametricGarment with the given measurements, 3 cm edges, cotton) with the solver settings of resources/scenes/
// garment_tshirt_walk.json, so `mannequin-cli simulate` can run a built-in
// garment on an imported character. Exit 0 when written, 1 on any error.
#include <cstdio>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "core/character/default_mannequin.h"
#include "core/garment/garment_json.h"
#include "core/garment/parametric_garments.h"
#include "core/io/character_import.h"
#include "core/scene/scene_document.h"
#include "core/util/error.h"

int main(int argc, char** argv) {
  if (argc < 5) {
    std::fprintf(stderr, "usage: %s CHARACTER TYPE CLIP OUT.json [NAME=VALUE ...]\n", argv[0]);
    return 1;
  }
  try {
    const std::string characterPath = argv[1];
    const mq::Character character =
        characterPath == "default" ? mq::makeDefaultMannequin() : mq::importCharacter(characterPath);
    std::map<std::string, float> measurements;
    for (int i = 5; i < argc; ++i) {
      const std::string assignment = argv[i];
      const size_t equals = assignment.find('=');
      if (equals == std::string::npos) throw mq::Error("expected NAME=VALUE, got '" + assignment + "'");
      measurements[assignment.substr(0, equals)] = std::stof(assignment.substr(equals + 1));
    }
    mq::Garment garment = mq::makeParametricGarment(argv[2], character, measurements);
    garment.targetEdgeLength = 0.03f;
    mq::SceneDocument document;
    document.character = characterPath;
    document.clip = std::string(argv[3]) == "rest" ? "" : argv[3];  // rest: the rest pose
    document.garments = nlohmann::json::array({mq::garmentToJson(garment)});
    document.cloth = {{"integrator", "implicit_euler"}, {"self_collisions", false}, {"thickness", 0.004},
                      {"stretch_limit", "position"},    {"max_stretch", 1.1},       {"fps", 30},
                      {"animate_body", true},           {"max_refinement", 1}};
    mq::saveSceneDocument(document, argv[4]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return 0;
}
