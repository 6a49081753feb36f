#pragma once
// Small garments shared by the garment tests.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/garment/garment.h"
#include "core/garment/garment_json.h"
#include "core/scene/open_scene.h"
#include "sim/cloth/cloth_scene_io.h"

namespace mq::test {

// Two 20 cm squares 5 cm apart at height `y`, sewn along the facing sides.
inline Garment twoSewnSquares(float y = 1.0f) {
  Garment g;
  g.name = "pair";
  g.targetEdgeLength = 0.05f;
  for (const char* name : {"left", "right"}) {
    Panel p;
    p.name = name;
    p.addLine("bottom", {0, 0});
    p.addLine("east", {0.2f, 0});
    p.addLine("top", {0.2f, 0.2f});
    p.addLine("west", {0, 0.2f});
    p.placement.center = {std::string(name) == "left" ? -0.2f : 0.05f, y, 0};
    g.panels.push_back(p);
  }
  g.seams.push_back({"left", "east", "right", "west", true});
  return g;
}

// tests/app/scenes/trousers_walk.json: the default mannequin's walk with
// trousers, its garments and cloth settings as read.
struct TrousersWalk {
  std::string file = std::string(MANNEQUIN_SOURCE_DIR) + "/tests/app/scenes/trousers_walk.json";
  LoadedScene scene = openScene(file);
  std::vector<Garment> garments = garmentsFromJson(scene.document.garments);
  cloth::ClothSceneSpec spec = cloth::parseClothScene(scene.document.cloth, scene.document.colliders, file, true);
  // What the tests on it take for granted: one garment and a clip to walk.
  ::testing::AssertionResult hasOneGarmentAndAClip() const {
    if (garments.size() != 1) return ::testing::AssertionFailure() << garments.size() << " garments, not 1";
    if (scene.clipIndex < 0) return ::testing::AssertionFailure() << "no clip";
    return ::testing::AssertionSuccess();
  }
};

}  // namespace mq::test
