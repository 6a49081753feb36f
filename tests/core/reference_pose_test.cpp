// Posed glTF characters against the independent reference poses in
// ../shared/assets/reference-poses (see its README.md): every listed
// (character, clip, time) must match within 1e-5 of the bbox diagonal.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/character/posed_character.h"
#include "core/io/character_import.h"

namespace mq {
namespace {

const std::string kAssets = std::string(MANNEQUIN_SHARED_DIR) + "/assets/";

std::vector<glm::dvec3> readObjVertices(const std::string& path) {
  std::ifstream in(path);
  std::vector<glm::dvec3> vertices;
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("v ", 0) != 0) continue;
    std::istringstream s(line.substr(2));
    glm::dvec3 v;
    s >> v.x >> v.y >> v.z;
    vertices.push_back(v);
  }
  return vertices;
}

nlohmann::json referenceIndex() {
  std::ifstream in(kAssets + "reference-poses/index.json");
  return nlohmann::json::parse(in);
}

TEST(ReferencePoses, IndexListsPoses) { EXPECT_GE(referenceIndex()["references"].size(), 12u); }

TEST(ReferencePoses, EveryPoseMatchesWithinTolerance) {
  const nlohmann::json index = referenceIndex();
  for (const auto& ref : index["references"]) {
    const std::string obj = ref["obj"].get<std::string>();
    SCOPED_TRACE(obj);
    const Character c = importCharacter(kAssets + ref["source"].get<std::string>());
    const int clip = ref["clip_index"].get<int>();
    ASSERT_LT(clip, static_cast<int>(c.clips.size()));
    PosedCharacter posed;
    posed.evaluate(c, clip, ref["time"].get<float>(), nullptr, nullptr);

    const auto expected = readObjVertices(kAssets + "reference-poses/" + obj);
    ASSERT_EQ(expected.size(), ref["vertex_count"].get<size_t>());
    ASSERT_EQ(c.vertexCount(), expected.size());
    ASSERT_EQ(c.triangleCount(), ref["face_count"].get<size_t>());
    const double tolerance = 1e-5 * ref["bbox_diagonal"].get<double>();
    double worst = 0.0;
    size_t v = 0;
    for (const PosedMesh& m : posed.meshes())
      for (size_t i = 0; i < m.positions.size() / 3; ++i, ++v) {
        const glm::dvec3 p(m.positions[3 * i], m.positions[3 * i + 1], m.positions[3 * i + 2]);
        worst = std::max(worst, glm::length(p - expected[v]));
      }
    EXPECT_LE(worst, tolerance) << "worst vertex error " << worst;
    std::cout << "[ reference ] " << obj << " from " << ref["source"].get<std::string>() << " max error " << worst
              << " (" << worst / ref["bbox_diagonal"].get<double>() << " x bbox diagonal)\n";
  }
}

}  // namespace
}  // namespace mq
