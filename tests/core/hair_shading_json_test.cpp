// The hairstyle's "shading": defaults that leave older files as they were,
// the model and pigments read from a style or from the section, bad values
// named.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/hair/hairstyle_json.h"
#include "core/util/error.h"

namespace mq {
namespace {

using nlohmann::json;

TEST(HairShadingJson, AbsentMeansKajiyaKayAndIsNotWritten) {
  const HairSection section = hairSectionFromJson(json{{"style", "wavy"}});
  EXPECT_EQ(section.style.shading.model, HairShadingModel::KajiyaKay);
  EXPECT_FALSE(toJson(section.style).contains("shading"));
  // A full style object saved before the field existed reads back to the same JSON.
  const json saved = toJson(builtinHairStyle("bob"));
  EXPECT_EQ(toJson(hairStyleFromJson(saved)), saved);
}

TEST(HairShadingJson, ReadFromTheSectionOrTheStyleAndWrittenBack) {
  const json j = {{"style", "long_straight"},
                  {"shading", {{"model", "physical"}, {"melanin", 0.3}, {"pheomelanin", 1.6}, {"roughness", 0.25}}}};
  const HairSection section = hairSectionFromJson(j);
  const HairShadingParams& s = section.style.shading;
  EXPECT_EQ(s.model, HairShadingModel::Physical);
  EXPECT_FLOAT_EQ(s.melanin, 0.3f);
  EXPECT_FLOAT_EQ(s.pheomelanin, 1.6f);
  EXPECT_FLOAT_EQ(s.roughness, 0.25f);
  const json written = toJson(section.style);
  ASSERT_TRUE(written.contains("shading"));
  EXPECT_EQ(written["shading"]["model"], "physical");
  EXPECT_EQ(hairStyleFromJson(written).shading, s);
  // Partial: the other fields keep their defaults.
  const HairStyle partial = hairStyleFromJson(json{{"preset", "bob"}, {"shading", {{"model", "physical"}}}});
  EXPECT_EQ(partial.shading.model, HairShadingModel::Physical);
  EXPECT_FLOAT_EQ(partial.shading.melanin, HairShadingParams{}.melanin);
}

TEST(HairShadingJson, BadValuesAreNamed) {
  EXPECT_THROW(hairSectionFromJson(json{{"shading", {{"model", "phong"}}}}), Error);
  EXPECT_THROW(hairSectionFromJson(json{{"shading", {{"melanin", -1.0}}}}), Error);
  EXPECT_THROW(hairSectionFromJson(json{{"shading", {{"roughness", 3.0}}}}), Error);
  EXPECT_THROW(hairSectionFromJson(json{{"shading", "physical"}}), Error);
}

// The style's "dynamics" (hair against hair) follow the same rules.
TEST(HairDynamicsJson, AbsentMeansOffReadWrittenAndBadValuesNamed) {
  const HairStyle plain = hairStyleFromJson(json("long_straight"));
  EXPECT_EQ(plain.dynamics, HairDynamicsParams{});
  EXPECT_FALSE(toJson(plain).contains("dynamics"));
  const HairStyle style =
      hairStyleFromJson(json{{"preset", "long_straight"}, {"dynamics", {{"volume", 0.5}, {"friction", 0.2}}}});
  EXPECT_FLOAT_EQ(style.dynamics.volume, 0.5f);
  EXPECT_FLOAT_EQ(style.dynamics.friction, 0.2f);
  const json written = toJson(style);
  ASSERT_TRUE(written.contains("dynamics"));
  EXPECT_EQ(hairStyleFromJson(written).dynamics, style.dynamics);
  try {
    hairSectionFromJson(json{{"style", {{"preset", "bob"}, {"dynamics", {{"volume", 1.5}}}}}});
    FAIL() << "a volume above 1 was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("hair.style.dynamics.volume"), std::string::npos) << e.what();
  }
  EXPECT_THROW(hairStyleFromJson(json{{"dynamics", {{"friction", -0.1}}}}), Error);
  EXPECT_THROW(hairStyleFromJson(json{{"dynamics", 0.5}}), Error);
  EXPECT_THROW(hairStyleFromJson(json{{"dynamics", {{"frction", 0.2}}}}), Error);  // a typo is not ignored

  // Adaptive wisps: off unless asked, written only when on, a boolean.
  EXPECT_FALSE(style.dynamics.adaptiveWisps);
  EXPECT_FALSE(written["dynamics"].contains("adaptive_wisps"));
  const HairStyle wisps = hairStyleFromJson(json{{"preset", "bob"}, {"dynamics", {{"adaptive_wisps", true}}}});
  EXPECT_TRUE(wisps.dynamics.adaptiveWisps);
  EXPECT_EQ(hairStyleFromJson(toJson(wisps)).dynamics, wisps.dynamics);
  EXPECT_THROW(hairStyleFromJson(json{{"dynamics", {{"adaptive_wisps", "yes"}}}}), Error);
}

}  // namespace
}  // namespace mq
