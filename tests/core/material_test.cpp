// Materials, textures and images read from files (glTF by our reader, FBX
// and Collada through Assimp), texture transforms and tangent frames.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "core/character/posed_character.h"
#include "core/io/character_import.h"
#include "core/material/material_override.h"
#include "core/mesh/tangents.h"
#include "core/scene/open_scene.h"
#include "core/util/error.h"
#include "gltf_test_util.h"

namespace mq {
namespace {

using nlohmann::json;
using test::Buffer;
using test::writeGltf;

const std::string kShared = MANNEQUIN_SHARED_DIR;

// Every triangle of every mesh is in exactly one material range.
void expectRangesCoverTriangles(const Character& c) {
  for (const Mesh& m : c.meshes) {
    uint32_t next = 0;
    for (const Submesh& r : m.drawRanges()) {
      EXPECT_EQ(r.firstTriangle, next) << m.name;
      next += r.triangleCount;
    }
    EXPECT_EQ(next, m.triangleCount()) << m.name;
  }
}

TEST(Materials, CesiumManKeepsItsTextureBesideTheFile) {
  const Character c = importCharacter(kShared + "/assets/characters/CesiumMan/glTF/CesiumMan.gltf");
  ASSERT_EQ(c.materials.size(), 1u);
  ASSERT_EQ(c.images.size(), 1u);
  const Material& m = c.materials[0];
  ASSERT_TRUE(m.baseColorTexture.present());
  EXPECT_EQ(c.images[0].name, "CesiumMan_img0.jpg");
  EXPECT_TRUE(std::filesystem::is_regular_file(c.images[0].path));
  EXPECT_TRUE(c.images[0].encoded.empty());
  EXPECT_TRUE(c.loadWarnings.empty());
  ASSERT_EQ(c.meshes.size(), 1u);
  EXPECT_EQ(c.meshes[0].drawRanges()[0].material, 0);
  EXPECT_EQ(c.meshes[0].uvs.size(), 2 * c.meshes[0].vertexCount());
  expectRangesCoverTriangles(c);
}

TEST(Materials, CesiumManGlbEmbedsItsJpeg) {
  const Character c = importCharacter(kShared + "/assets/characters/CesiumMan/glTF-Binary/CesiumMan.glb");
  ASSERT_EQ(c.images.size(), 1u);
  const ImageSource& image = c.images[0];
  ASSERT_GT(image.encoded.size(), 1000u);
  EXPECT_EQ(image.encoded[0], 0xFF);  // JPEG start-of-image marker
  EXPECT_EQ(image.encoded[1], 0xD8);
  EXPECT_EQ(image.mimeType, "image/jpeg");
  EXPECT_TRUE(image.path.empty());
}

// A quad in two primitives with two materials, every glTF material feature
// the samples lack set to a non-default value.
std::string writeTwoMaterialQuad(const std::string& name, json materialOverrides = json::object()) {
  Buffer b;
  const size_t positions = b.add(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0});
  const size_t normals = b.add(std::vector<float>{0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1});
  const size_t uvs = b.add(std::vector<float>{0, 1, 1, 1, 0, 0, 1, 0});
  const size_t first = b.add(std::vector<uint16_t>{0, 1, 2});
  const size_t second = b.add(std::vector<uint16_t>{1, 3, 2});
  json g;
  g["bufferViews"] = {{{"buffer", 0}, {"byteOffset", positions}, {"byteLength", 48}},
                      {{"buffer", 0}, {"byteOffset", normals}, {"byteLength", 48}},
                      {{"buffer", 0}, {"byteOffset", uvs}, {"byteLength", 32}},
                      {{"buffer", 0}, {"byteOffset", first}, {"byteLength", 6}},
                      {{"buffer", 0}, {"byteOffset", second}, {"byteLength", 6}}};
  g["accessors"] = {{{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
                    {{"bufferView", 1}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
                    {{"bufferView", 2}, {"componentType", 5126}, {"count", 4}, {"type", "VEC2"}},
                    {{"bufferView", 3}, {"componentType", 5123}, {"count", 3}, {"type", "SCALAR"}},
                    {{"bufferView", 4}, {"componentType", 5123}, {"count", 3}, {"type", "SCALAR"}}};
  const json attributes = {{"POSITION", 0}, {"NORMAL", 1}, {"TEXCOORD_0", 2}};
  g["meshes"] = {{{"primitives",
                   {{{"attributes", attributes}, {"indices", 3}, {"material", 1}},
                    {{"attributes", attributes}, {"indices", 4}, {"material", 0}}}}}};
  g["nodes"] = {{{"mesh", 0}}};
  g["scenes"] = {{{"nodes", {0}}}};
  g["images"] = {{{"uri", "missing_albedo.png"}}, {{"uri", "data:image/png;base64,iVBORw0KGgo="}}};
  g["samplers"] = {{{"wrapS", 33071}, {"wrapT", 33648}, {"magFilter", 9728}, {"minFilter", 9729}}};
  g["textures"] = {{{"source", 0}, {"sampler", 0}}, {{"source", 1}}};
  g["materials"] = {
      {{"name", "cloth"},
       {"pbrMetallicRoughness",
        {{"baseColorFactor", {0.5, 0.25, 0.125, 0.75}},
         {"baseColorTexture",
          {{"index", 0},
           {"extensions",
            {{"KHR_texture_transform", {{"offset", {0.5, 0}}, {"rotation", 1.5707963}, {"scale", {2, 2}}}}}}}},
         {"metallicFactor", 0.0},
         {"roughnessFactor", 0.4}}},
       {"normalTexture", {{"index", 1}, {"scale", 0.5}}},
       {"emissiveFactor", {1, 0.5, 0}},
       {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4.0}}}}},
       {"alphaMode", "MASK"},
       {"alphaCutoff", 0.3},
       {"doubleSided", true}},
      {{"name", "plain"}}};
  for (auto& [key, value] : materialOverrides.items()) g["materials"][0][key] = value;
  return writeGltf(name, g, b);
}

TEST(Materials, GltfMaterialFeaturesAreRead) {
  const Character c = importCharacter(writeTwoMaterialQuad("materials.gltf"));
  ASSERT_EQ(c.materials.size(), 2u);
  const Material& m = c.materials[0];
  EXPECT_EQ(m.name, "cloth");
  EXPECT_EQ(m.baseColorFactor, glm::vec4(0.5f, 0.25f, 0.125f, 0.75f));
  EXPECT_FLOAT_EQ(m.metallicFactor, 0.0f);
  EXPECT_FLOAT_EQ(m.roughnessFactor, 0.4f);
  EXPECT_FLOAT_EQ(m.normalScale, 0.5f);
  EXPECT_EQ(m.emissiveFactor, glm::vec3(1.0f, 0.5f, 0.0f));
  EXPECT_FLOAT_EQ(m.emissiveStrength, 4.0f);
  EXPECT_EQ(m.alphaMode, AlphaMode::Mask);
  EXPECT_FLOAT_EQ(m.alphaCutoff, 0.3f);
  EXPECT_TRUE(m.doubleSided);
  EXPECT_EQ(m.baseColorTexture.image, 0);
  EXPECT_EQ(m.baseColorTexture.sampler.wrapS, TextureWrap::ClampToEdge);
  EXPECT_EQ(m.baseColorTexture.sampler.wrapT, TextureWrap::MirroredRepeat);
  EXPECT_FALSE(m.baseColorTexture.sampler.linear);
  EXPECT_FALSE(m.baseColorTexture.sampler.mipmaps);
  EXPECT_FLOAT_EQ(m.baseColorTexture.transform.scale.x, 2.0f);
  EXPECT_EQ(m.normalTexture.image, 1);
  // The second material has every default.
  const Material& plain = c.materials[1];
  EXPECT_EQ(plain.baseColorFactor, glm::vec4(1.0f));
  EXPECT_FLOAT_EQ(plain.metallicFactor, 1.0f);
  EXPECT_EQ(plain.alphaMode, AlphaMode::Opaque);
  EXPECT_FALSE(plain.doubleSided);
  EXPECT_FALSE(plain.textured());

  // Primitives keep their own material, in order.
  ASSERT_EQ(c.meshes.size(), 1u);
  const std::vector<Submesh> ranges = c.meshes[0].drawRanges();
  ASSERT_EQ(ranges.size(), 2u);
  EXPECT_EQ(ranges[0].material, 1);
  EXPECT_EQ(ranges[1].material, 0);
  expectRangesCoverTriangles(c);

  // The normal map asks for tangents, which the file lacks: computed, +u.
  const Mesh& mesh = c.meshes[0];
  ASSERT_EQ(mesh.tangents.size(), 4 * mesh.vertexCount());
  for (uint32_t v : mesh.triangles) {  // each primitive leaves one of its vertices unused
    EXPECT_NEAR(mesh.tangents[4 * v], 1.0f, 1e-5f);
    EXPECT_NEAR(mesh.tangents[4 * v + 1], 0.0f, 1e-5f);
    // The image stands upright on the quad (v grows downwards, y up): right-handed.
    EXPECT_EQ(mesh.tangents[4 * v + 3], 1.0f);
  }

  // Images: a data URI decoded, a missing file a warning that names it.
  ASSERT_EQ(c.images.size(), 2u);
  EXPECT_EQ(c.images[1].mimeType, "image/png");
  EXPECT_EQ(c.images[1].encoded.size(), 8u);  // the PNG signature
  EXPECT_EQ(c.images[0].name, "missing_albedo.png");
  ASSERT_EQ(c.loadWarnings.size(), 1u);
  EXPECT_NE(c.loadWarnings[0].find("missing_albedo.png"), std::string::npos);
  EXPECT_NE(c.loadWarnings[0].find("materials.gltf"), std::string::npos);
}

TEST(Materials, BadMaterialsAreErrorsNamingTheFile) {
  const std::string badAlpha = writeTwoMaterialQuad("bad_alpha.gltf", {{"alphaMode", "GLOWING"}});
  try {
    importCharacter(badAlpha);
    FAIL() << "an unknown alphaMode must be refused";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("bad_alpha.gltf"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("GLOWING"), std::string::npos);
  }
  const std::string badTexture = writeTwoMaterialQuad("bad_texture.gltf", {{"normalTexture", {{"index", 7}}}});
  try {
    importCharacter(badTexture);
    FAIL() << "a texture index out of range must be refused";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("bad_texture.gltf"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("textures[7]"), std::string::npos);
  }
}

TEST(Materials, TextureTransformFollowsTheExtensionsMatrix) {
  TextureTransform t;
  EXPECT_TRUE(t.identity());
  t.rotation = static_cast<float>(M_PI / 2);
  const glm::vec2 turned = t.apply({1.0f, 0.0f});
  EXPECT_NEAR(turned.x, 0.0f, 1e-6f);
  EXPECT_NEAR(turned.y, -1.0f, 1e-6f);
  t = TextureTransform{};
  t.offset = {0.5f, 0.25f};
  t.scale = {2.0f, 3.0f};
  const glm::vec2 moved = t.apply({1.0f, 1.0f});
  EXPECT_FLOAT_EQ(moved.x, 2.5f);
  EXPECT_FLOAT_EQ(moved.y, 3.25f);
}

TEST(Materials, SrgbRoundTrips) {
  for (float c : {0.0f, 0.002f, 0.04f, 0.2f, 0.5f, 0.9f, 1.0f}) EXPECT_NEAR(linearToSrgb(srgbToLinear(c)), c, 1e-5f);
  EXPECT_NEAR(srgbToLinear(0.5f), 0.2140f, 1e-4f);
}

TEST(Tangents, FollowTheUvsOnAPlane) {
  const std::vector<float> positions{0, 0, 0, 1, 0, 0, 0, 1, 0};
  const std::vector<float> normals{0, 0, 1, 0, 0, 1, 0, 0, 1};
  const std::vector<uint32_t> triangles{0, 1, 2};
  std::vector<float> tangents;
  // u along y, v along -x (the image's top towards +x): a mirrored layout,
  // the tangent is +y and the frame left-handed.
  computeVertexTangents(positions, normals, {0, 0, 0, -1, 1, 0}, triangles, tangents);
  ASSERT_EQ(tangents.size(), 12u);
  EXPECT_NEAR(tangents[0], 0.0f, 1e-6f);
  EXPECT_NEAR(tangents[1], 1.0f, 1e-6f);
  EXPECT_EQ(tangents[3], -1.0f);
  // Degenerate uvs still give a unit tangent perpendicular to the normal.
  computeVertexTangents(positions, normals, {0, 0, 0, 0, 0, 0}, triangles, tangents);
  const glm::vec3 t(tangents[0], tangents[1], tangents[2]);
  EXPECT_NEAR(glm::length(t), 1.0f, 1e-6f);
  EXPECT_NEAR(t.z, 0.0f, 1e-6f);
}

TEST(Tangents, AreCarriedByTheNormalsRotation) {
  // Normal +z turned to +y (a quarter turn about -x... i.e. about x by -90
  // degrees): a tangent along +y goes to -z; one along +x stays.
  const std::vector<float> restNormals{0, 0, 1, 0, 0, 1};
  const std::vector<float> restTangents{0, 1, 0, 1, 1, 0, 0, -1};
  const std::vector<float> posedNormals{0, 1, 0, 0, 1, 0};
  std::vector<float> posed;
  carryTangents(restNormals, restTangents, posedNormals, posed);
  ASSERT_EQ(posed.size(), 8u);
  EXPECT_NEAR(posed[0], 0.0f, 1e-6f);
  EXPECT_NEAR(posed[1], 0.0f, 1e-6f);
  EXPECT_NEAR(posed[2], -1.0f, 1e-6f);
  EXPECT_EQ(posed[3], 1.0f);
  EXPECT_NEAR(posed[4], 1.0f, 1e-6f);
  EXPECT_NEAR(posed[6], 0.0f, 1e-6f);
  EXPECT_EQ(posed[7], -1.0f);
}

TEST(Materials, ColladaAndFbxMaterialsAreRead) {
  for (const char* file : {"/assets/characters/assimp_collada_library_animation_clips/library_animation_clips.dae",
                           "/assets/characters/assimp_fbx_animation_with_skeleton/animation_with_skeleton.fbx"}) {
    const Character c = importCharacter(kShared + file);
    SCOPED_TRACE(file);
    for (const Mesh& m : c.meshes) {
      ASSERT_GE(m.material, 0);
      ASSERT_LT(m.material, static_cast<int>(c.materials.size()));
    }
    for (const Material& m : c.materials) {
      EXPECT_FALSE(m.name.empty());
      EXPECT_EQ(m.metallicFactor, 0.0f);
      EXPECT_GT(m.roughnessFactor, 0.0f);
    }
  }
}

}  // namespace
}  // namespace mq

namespace mq {
namespace {

TEST(MaterialOverrides, KeepOnlyWhatChangedAndRoundTrip) {
  Material original;
  original.name = "coat";
  Material edited = original;
  EXPECT_TRUE(MaterialOverride::between(original, edited).empty());
  edited.roughnessFactor = 0.3f;
  edited.baseColorFactor = {0.2f, 0.4f, 0.6f, 0.5f};
  edited.alphaMode = AlphaMode::Blend;
  edited.skin = true;
  const MaterialOverride changes = MaterialOverride::between(original, edited);
  EXPECT_FALSE(changes.metallic.has_value());
  EXPECT_FALSE(changes.doubleSided.has_value());
  const nlohmann::json j = changes.toJson();
  EXPECT_EQ(j.size(), 4u);
  const MaterialOverride back = MaterialOverride::fromJson(j, "materials.coat");
  Material applied = original;
  back.applyTo(applied);
  EXPECT_TRUE(MaterialOverride::between(edited, applied).empty());
  EXPECT_EQ(applied.alphaMode, AlphaMode::Blend);
}

TEST(MaterialOverrides, BadValuesNameTheField) {
  auto problem = [](const nlohmann::json& j) -> std::string {
    try {
      MaterialOverride::fromJson(j, "materials.coat");
    } catch (const Error& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(problem({{"roughness", 2.0}}).find("materials.coat.roughness"), std::string::npos);
  EXPECT_NE(problem({{"base_color", {1, 0, 0}}}).find("materials.coat.base_color"), std::string::npos);
  EXPECT_NE(problem({{"alpha_mode", "CLEAR"}}).find("alpha_mode"), std::string::npos);
  EXPECT_NE(problem({{"shininess", 3}}).find("unknown field 'shininess'"), std::string::npos);
  EXPECT_NE(problem({{"skin", "yes"}}).find("materials.coat.skin"), std::string::npos);
  EXPECT_EQ(problem({{"metallic", 1.0}, {"double_sided", true}}), "");
}

TEST(MaterialOverrides, SceneDocumentAppliesThemByNameAndWarnsOfUnknownNames) {
  const std::string cesium = kShared + "/assets/characters/CesiumMan/glTF/CesiumMan.gltf";
  const std::string text = R"({"format": "mannequin-scene", "version": 1, "character": ")" + cesium +
                           R"(", "view": {"look": "plain"},
      "materials": {"Cesium_Man-effect": {"roughness": 0.25}, "Cape": {"metallic": 1.0}}})";
  const SceneDocument doc = parseSceneDocument(text, "scene.mqscene");
  EXPECT_EQ(doc.view.look, "plain");
  const LoadedScene scene = resolveSceneDocument(doc, "");
  ASSERT_EQ(scene.character.materials.size(), 1u);
  EXPECT_FLOAT_EQ(scene.character.materials[0].roughnessFactor, 0.25f);
  EXPECT_FLOAT_EQ(scene.fileMaterials[0].roughnessFactor, 1.0f);
  ASSERT_EQ(scene.character.loadWarnings.size(), 1u);
  EXPECT_NE(scene.character.loadWarnings[0].find("'Cape'"), std::string::npos);
  // Saved again, both changes are kept (the unknown one too).
  const nlohmann::json saved = toJson(doc);
  EXPECT_EQ(saved["materials"].size(), 2u);
  EXPECT_EQ(saved["view"]["look"], "plain");
  EXPECT_THROW(parseSceneDocument(R"({"format": "mannequin-scene", "version": 1, "view": {"look": "shiny"}})", "x"),
               FileError);
}

}  // namespace
}  // namespace mq

namespace mq {
namespace {

// Static meshes (OBJ, PLY, STL through Assimp) open as characters without
// bones; their units are guessed from their height.
TEST(StaticMeshes, ObjHeadOpensWeldedWithAUnitNotice) {
  const Character head = importCharacter(kShared + "/assets/heads/makehuman_hm08_head/makehuman_head.obj");
  EXPECT_EQ(head.skeleton.boneCount(), 0);
  ASSERT_EQ(head.meshes.size(), 1u);
  // Welded: far fewer vertices than face corners.
  EXPECT_LT(head.meshes[0].vertexCount(), head.meshes[0].triangleCount());
  EXPECT_NE(head.unitNotice.find("decimetres"), std::string::npos) << head.unitNotice;
  EXPECT_NE(head.unitNotice.find("--scale 0.1"), std::string::npos) << head.unitNotice;
  PosedCharacter posed;
  posed.evaluate(head, -1, 0.0f, nullptr, nullptr);
  EXPECT_EQ(posed.meshes()[0].positions, head.meshes[0].positions);
}

TEST(StaticMeshes, PlyAndStlOpen) {
  const auto dir = test::scratchDir("mq_static");
  const std::string ply = (dir / "tet.ply").string(), stl = (dir / "tet.stl").string();
  std::ofstream(ply)
      << "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
         "element face 4\nproperty list uchar int vertex_indices\nend_header\n"
         "0 0 0\n1 0 0\n0 1.7 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  std::ofstream(stl)
      << "solid t\nfacet normal 0 0 -1\nouter loop\nvertex 0 0 0\nvertex 0 170 0\nvertex 100 0 0\n"
         "endloop\nendfacet\nfacet normal 0 -1 0\nouter loop\nvertex 0 0 0\nvertex 100 0 0\nvertex 0 0 100\n"
         "endloop\nendfacet\nendsolid t\n";
  const Character tet = importCharacter(ply);
  ASSERT_EQ(tet.meshes.size(), 1u);
  EXPECT_EQ(tet.meshes[0].triangleCount(), 4u);
  EXPECT_TRUE(tet.unitNotice.empty()) << "1.7 units tall reads as metres";
  const Character shape = importCharacter(stl);
  ASSERT_EQ(shape.meshes.size(), 1u);
  EXPECT_EQ(shape.meshes[0].vertexCount(), 4u) << "STL corners welded";
  EXPECT_NE(shape.unitNotice.find("centimetres"), std::string::npos) << shape.unitNotice;
}

TEST(StaticMeshes, ScalingACharacterScalesItsPosesExactly) {
  const Character original = importCharacter(kShared + "/assets/characters/CesiumMan/glTF/CesiumMan.gltf");
  Character scaled = original;
  scaled.scaleUniformly(0.01f);
  PosedCharacter a, b;
  a.evaluate(original, 0, 0.7f, nullptr, nullptr);
  b.evaluate(scaled, 0, 0.7f, nullptr, nullptr);
  const std::vector<float>& pa = a.meshes()[0].positions;
  const std::vector<float>& pb = b.meshes()[0].positions;
  ASSERT_EQ(pa.size(), pb.size());
  float worst = 0.0f;
  for (size_t i = 0; i < pa.size(); ++i) worst = std::max(worst, std::abs(pa[i] * 0.01f - pb[i]));
  EXPECT_LT(worst, 1e-6f);
  const SceneDocument doc = parseSceneDocument(
      R"({"format": "mannequin-scene", "version": 1, "character": "default", "scale": 2})", "s.mqscene");
  EXPECT_FLOAT_EQ(doc.scale, 2.0f);
  EXPECT_FLOAT_EQ(toJson(doc)["scale"].get<float>(), 2.0f);
  EXPECT_THROW(parseSceneDocument(R"({"format": "mannequin-scene", "version": 1, "scale": -1})", "s"), FileError);
}

}  // namespace
}  // namespace mq
