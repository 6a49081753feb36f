// A scene document and every section it holds: hair, garments, cloth and
// colliders, materials, skinning.
#include <nlohmann/json.hpp>

#include "core/garment/garment_json.h"
#include "core/hair/hairstyle_json.h"
#include "core/scene/scene_document.h"
#include "fuzz_input.h"
#include "sim/cloth/cloth_scene_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  mq::fuzz::expectOnlyErrors([&] {
    const mq::SceneDocument doc = mq::parseSceneDocument(text, "scene.mqscene");
    mq::fuzz::expectOnlyErrors([&] { mq::hairSectionFromJson(doc.hair); });
    const bool hasGarments = doc.garments.is_array() && !doc.garments.empty();
    if (hasGarments)
      for (size_t i = 0; i < doc.garments.size(); ++i)
        mq::fuzz::expectOnlyErrors(
            [&] { mq::garmentFromJson(doc.garments[i], "garments[" + std::to_string(i) + "]"); });
    mq::fuzz::expectOnlyErrors(
        [&] { mq::cloth::parseClothScene(doc.cloth, doc.colliders, "scene.mqscene", hasGarments); });
    // What is read must write back and read again.
    mq::parseSceneDocument(mq::toJson(doc).dump(), "again.mqscene");
  });
  return 0;
}
