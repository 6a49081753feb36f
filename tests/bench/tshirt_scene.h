#pragma once
// The 10k-vertex T-shirt benchmark scene (tests/bench/scenes/tshirt_walk_10k.json)
// as the benchmarks that start from its garment need it.

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/garment/garment_json.h"
#include "sim/cloth/cloth_scene_io.h"

namespace mq::bench {

struct TShirtScene {
  std::string path;
  std::vector<mq::Garment> garments;
  mq::cloth::ClothSceneSpec spec;  // its cloth settings
};

inline TShirtScene loadTShirtScene() {
  TShirtScene scene;
  scene.path = std::string(MANNEQUIN_SOURCE_DIR) + "/tests/bench/scenes/tshirt_walk_10k.json";
  std::ifstream in(scene.path);
  std::stringstream text;
  text << in.rdbuf();
  const nlohmann::json doc = nlohmann::json::parse(text.str());
  scene.garments = mq::garmentsFromJson(doc["garments"]);
  scene.spec = mq::cloth::parseClothScene(doc["cloth"], nlohmann::json(), scene.path, true);
  return scene;
}

}  // namespace mq::bench
