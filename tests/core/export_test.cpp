// Posed meshes written as OBJ and PLY read back to the same vertices (in
// importer order, no welding), normals and triangles; the writes are atomic.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include "core/character/posed_character.h"
#include "core/io/character_import.h"
#include "core/io/file_bytes.h"
#include "core/io/mesh_export.h"
#include "core/util/error.h"
#include "import_test_util.h"

namespace mq {
namespace {

struct MeshData {
  std::vector<float> positions, normals;
  std::vector<uint32_t> triangles;
};

std::string tempPath(const std::string& name) {
  const auto dir = test::scratchDir("mq_export_test");
  return (dir / name).string();
}

MeshData readObj(const std::string& path) {
  MeshData m;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string tag;
    s >> tag;
    float x, y, z;
    if (tag == "v" && s >> x >> y >> z) m.positions.insert(m.positions.end(), {x, y, z});
    if (tag == "vn" && s >> x >> y >> z) m.normals.insert(m.normals.end(), {x, y, z});
    if (tag == "f")
      for (std::string corner; s >> corner;) m.triangles.push_back(std::stoul(corner.substr(0, corner.find('/'))) - 1);
  }
  return m;
}

MeshData readBinaryPly(const std::string& path) {
  const std::string bytes = loadFileText(path);
  const size_t header = bytes.find("end_header\n");
  EXPECT_NE(header, std::string::npos);
  EXPECT_NE(bytes.find("format binary_little_endian 1.0"), std::string::npos);
  auto count = [&](const char* element) {
    const size_t at = bytes.find(element);
    return at < header ? std::stoul(bytes.substr(at + std::strlen(element))) : 0ul;
  };
  const size_t vertices = count("element vertex "), faces = count("element face ");
  MeshData m;
  const char* p = bytes.data() + header + std::strlen("end_header\n");
  for (size_t v = 0; v < vertices; ++v) {
    float f[6];
    std::memcpy(f, p, sizeof f);
    p += sizeof f;
    m.positions.insert(m.positions.end(), f, f + 3);
    m.normals.insert(m.normals.end(), f + 3, f + 6);
  }
  for (size_t t = 0; t < faces; ++t) {
    EXPECT_EQ(static_cast<uint8_t>(*p), 3);
    int32_t idx[3];
    std::memcpy(idx, p + 1, sizeof idx);
    p += 1 + sizeof idx;
    m.triangles.insert(m.triangles.end(), idx, idx + 3);
  }
  EXPECT_EQ(p, bytes.data() + bytes.size());
  return m;
}

// CesiumMan mid-clip: the whole posed character as one flat list.
struct Fixture {
  Character character =
      importCharacter(std::string(MANNEQUIN_SHARED_DIR) + "/assets/characters/CesiumMan/glTF/CesiumMan.gltf");
  PosedCharacter posed;
  MeshData expected;
  Fixture() {
    posed.evaluate(character, 0, 0.9f, nullptr, nullptr);
    uint32_t base = 0;
    for (size_t i = 0; i < character.meshes.size(); ++i) {
      const PosedMesh& pm = posed.meshes()[i];
      expected.positions.insert(expected.positions.end(), pm.positions.begin(), pm.positions.end());
      expected.normals.insert(expected.normals.end(), pm.normals.begin(), pm.normals.end());
      for (uint32_t t : character.meshes[i].triangles) expected.triangles.push_back(base + t);
      base += static_cast<uint32_t>(character.meshes[i].vertexCount());
    }
  }
};

TEST(Export, ObjRoundTripIsExact) {
  Fixture f;
  const std::string path = tempPath("cesium.obj");
  exportPosedCharacter(f.character, f.posed, path);
  const MeshData back = readObj(path);
  EXPECT_EQ(back.positions, f.expected.positions);  // %.9g keeps every float bit
  EXPECT_EQ(back.normals, f.expected.normals);
  EXPECT_EQ(back.triangles, f.expected.triangles);
}

TEST(Export, PlyRoundTripIsExact) {
  Fixture f;
  const std::string path = tempPath("cesium.ply");
  exportPosedCharacter(f.character, f.posed, path);
  const MeshData back = readBinaryPly(path);
  EXPECT_EQ(back.positions, f.expected.positions);
  EXPECT_EQ(back.normals, f.expected.normals);
  EXPECT_EQ(back.triangles, f.expected.triangles);
}

// Our own glTF reader reads the export back in the same vertex order.
void expectGltfRoundTrip(const std::string& extension) {
  Fixture f;
  const std::string path = tempPath("cesium." + extension);
  exportPosedCharacter(f.character, f.posed, path);
  const Character back = importCharacter(path);
  ASSERT_EQ(back.meshes.size(), f.character.meshes.size());
  EXPECT_EQ(back.skeleton.boneCount(), 0);
  MeshData got;
  uint32_t base = 0;
  for (const Mesh& m : back.meshes) {
    EXPECT_TRUE(m.skin.empty());
    got.positions.insert(got.positions.end(), m.positions.begin(), m.positions.end());
    got.normals.insert(got.normals.end(), m.normals.begin(), m.normals.end());
    for (uint32_t t : m.triangles) got.triangles.push_back(base + t);
    base += static_cast<uint32_t>(m.vertexCount());
  }
  EXPECT_EQ(got.positions, f.expected.positions);
  EXPECT_EQ(got.normals, f.expected.normals);
  EXPECT_EQ(got.triangles, f.expected.triangles);
  EXPECT_EQ(back.meshes[0].uvs, f.character.meshes[0].uvs);
}

TEST(Export, GlbRoundTripIsExact) { expectGltfRoundTrip("glb"); }
TEST(Export, GltfRoundTripIsExact) { expectGltfRoundTrip("gltf"); }

TEST(Export, PosedDiffersFromRest) {
  Fixture f;
  PosedCharacter rest;
  rest.evaluate(f.character, -1, 0.0f, nullptr, nullptr);
  EXPECT_NE(rest.meshes()[0].positions, f.posed.meshes()[0].positions);
}

TEST(Export, UnknownExtensionAndUnwritablePathThrow) {
  Fixture f;
  EXPECT_THROW(exportPosedCharacter(f.character, f.posed, tempPath("cesium.stl")), FileError);
  EXPECT_THROW(exportPosedCharacter(f.character, f.posed, tempPath("no/such/dir/cesium.obj")), FileError);
}

TEST(Export, FailedWriteLeavesThePreviousFile) {
  Fixture f;
  const std::string path = tempPath("keep.obj");
  std::ofstream(path) << "previous";
  std::vector<const Mesh*> meshes{&f.character.meshes[0]};
  std::vector<PosedMesh> wrong(1);  // vertex count mismatch: refused before writing
  EXPECT_THROW(exportPosedMesh(meshes, wrong, path), Error);
  EXPECT_EQ(loadFileText(path), "previous");
  for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(path).parent_path()))
    EXPECT_EQ(entry.path().string().find(".tmp-"), std::string::npos) << "temporary file left behind";
}

}  // namespace
}  // namespace mq
