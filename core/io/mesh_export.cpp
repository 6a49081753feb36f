#include "core/io/mesh_export.h"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <map>
#include <ostream>

#include "core/io/file_bytes.h"
#include "core/io/gltf_material_export.h"
#include "core/io/gltf_writer.h"
#include "core/util/atomic_file.h"
#include "core/util/error.h"

namespace mq {
namespace {

// Nine significant digits: a float survives the text round trip exactly.
void writeFloats(std::ostream& out, const char* prefix, const float* v, int n) {
  char buffer[128];
  int len = std::snprintf(buffer, sizeof buffer, "%s", prefix);
  for (int i = 0; i < n; ++i) len += std::snprintf(buffer + len, sizeof buffer - len, " %.9g", v[i]);
  out.write(buffer, len);
  out.put('\n');
}

void writeObj(std::ostream& out, const std::vector<const Mesh*>& meshes, const std::vector<PosedMesh>& posed) {
  out << "# mannequin posed mesh: world-space positions, vertices in importer order\n";
  size_t base = 1, uvBase = 1;
  for (size_t m = 0; m < meshes.size(); ++m) {
    const Mesh& mesh = *meshes[m];
    const PosedMesh& p = posed[m];
    const size_t n = p.positions.size() / 3;
    const bool normals = p.normals.size() == 3 * n;
    const bool uvs = mesh.uvs.size() == 2 * n;
    out << "o " << (mesh.name.empty() ? "mesh" + std::to_string(m) : mesh.name) << "\n";
    for (size_t v = 0; v < n; ++v) writeFloats(out, "v", &p.positions[3 * v], 3);
    if (normals)
      for (size_t v = 0; v < n; ++v) writeFloats(out, "vn", &p.normals[3 * v], 3);
    if (uvs)
      for (size_t v = 0; v < n; ++v) {
        const float objUv[2] = {mesh.uvs[2 * v], 1.0f - mesh.uvs[2 * v + 1]};  // OBJ's origin is bottom left
        writeFloats(out, "vt", objUv, 2);
      }
    for (size_t t = 0; t + 2 < mesh.triangles.size(); t += 3) {
      out << "f";
      for (int c = 0; c < 3; ++c) {
        const size_t i = mesh.triangles[t + c];
        out << ' ' << base + i;
        if (uvs || normals) out << '/';
        if (uvs) out << uvBase + i;
        if (normals) out << '/' << base + i;
      }
      out << '\n';
    }
    base += n;
    if (uvs) uvBase += n;
  }
}

template <typename T>
void put(std::ostream& out, T value) {
  out.write(reinterpret_cast<const char*>(&value), sizeof value);  // little-endian hosts only
}

void writePly(std::ostream& out, const std::vector<const Mesh*>& meshes, const std::vector<PosedMesh>& posed) {
  size_t vertices = 0, triangles = 0;
  for (size_t m = 0; m < meshes.size(); ++m) {
    vertices += posed[m].positions.size() / 3;
    triangles += meshes[m]->triangleCount();
  }
  out << "ply\nformat binary_little_endian 1.0\ncomment mannequin posed mesh, world space\n";
  for (size_t m = 0; m < meshes.size(); ++m)
    out << "comment mesh " << meshes[m]->name << " vertices " << posed[m].positions.size() / 3 << "\n";
  out << "element vertex " << vertices
      << "\nproperty float x\nproperty float y\nproperty float z\n"
         "property float nx\nproperty float ny\nproperty float nz\n"
      << "element face " << triangles << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (size_t m = 0; m < meshes.size(); ++m) {
    const PosedMesh& p = posed[m];
    const size_t n = p.positions.size() / 3;
    for (size_t v = 0; v < n; ++v) {
      for (int d = 0; d < 3; ++d) put(out, p.positions[3 * v + d]);
      for (int d = 0; d < 3; ++d) put(out, p.normals.size() == 3 * n ? p.normals[3 * v + d] : 0.0f);
    }
  }
  int32_t base = 0;
  for (size_t m = 0; m < meshes.size(); ++m) {
    const std::vector<uint32_t>& tri = meshes[m]->triangles;
    for (size_t t = 0; t + 2 < tri.size(); t += 3) {
      put(out, uint8_t(3));
      for (int c = 0; c < 3; ++c) put(out, static_cast<int32_t>(base + tri[t + c]));
    }
    base += static_cast<int32_t>(posed[m].positions.size() / 3);
  }
}

// --- glTF 2.0 (static meshes, world space) --------------------------------

// materials: the character whose materials the meshes use, or null.
void buildGltf(GltfWriter& writer, const std::vector<const Mesh*>& meshes, const std::vector<PosedMesh>& posed,
               const Character* materials) {
  if (materials) addGltfMaterials(writer, *materials);  // a missing image leaves its texture out
  const size_t materialCount = materials ? materials->materials.size() : 0;
  for (size_t m = 0; m < meshes.size(); ++m) {
    const Mesh& mesh = *meshes[m];
    const PosedMesh& p = posed[m];
    const size_t n = p.positions.size() / 3;
    std::map<std::string, int> attributes = {{"POSITION", writer.addPositionAccessor(p.positions)}};
    if (p.normals.size() == 3 * n) attributes["NORMAL"] = writer.addVertexAttribute(p.normals, TINYGLTF_TYPE_VEC3);
    if (mesh.uvs.size() == 2 * n) attributes["TEXCOORD_0"] = writer.addVertexAttribute(mesh.uvs, TINYGLTF_TYPE_VEC2);
    tinygltf::Mesh gltfMesh;
    gltfMesh.name = mesh.name;
    gltfMesh.primitives = gltfPrimitives(writer, mesh, attributes, materialCount);
    writer.model().meshes.push_back(std::move(gltfMesh));
    tinygltf::Node node;
    node.name = mesh.name;
    node.mesh = int(writer.model().meshes.size()) - 1;
    writer.addNode(std::move(node), true);
  }
}

void writeGltf(std::ostream& out, const std::vector<const Mesh*>& meshes, const std::vector<PosedMesh>& posed,
               const Character* materials, bool binary) {
  GltfWriter writer("mannequin posed-mesh export");
  buildGltf(writer, meshes, posed, materials);
  writer.write(out, binary);
}

}  // namespace

bool isMeshExportPath(const std::string& path) {
  const std::string ext = fileExtension(path);
  return ext == "obj" || ext == "ply" || ext == "gltf" || ext == "glb";
}

void exportPosedMesh(const std::vector<const Mesh*>& meshes, const std::vector<PosedMesh>& posed,
                     const std::string& path, const Character* materials) {
  if (meshes.size() != posed.size()) throw Error("exportPosedMesh: mesh and posed-mesh counts differ");
  for (size_t m = 0; m < meshes.size(); ++m)
    if (posed[m].positions.size() != meshes[m]->positions.size())
      throw Error("exportPosedMesh: posed mesh '" + meshes[m]->name + "' has a different vertex count");
  const std::string ext = fileExtension(path);
  if (ext == "obj")
    writeFileAtomically(path, [&](std::ostream& out) { writeObj(out, meshes, posed); });
  else if (ext == "ply")
    writeFileAtomically(
        path, [&](std::ostream& out) { writePly(out, meshes, posed); }, true);
  else if (ext == "gltf")
    writeFileAtomically(path, [&](std::ostream& out) { writeGltf(out, meshes, posed, materials, false); });
  else if (ext == "glb")
    writeFileAtomically(
        path, [&](std::ostream& out) { writeGltf(out, meshes, posed, materials, true); }, true);
  else
    throw FileError(path, "cannot export to '." + ext + "' (use .obj, .ply, .gltf or .glb)");
}

void exportPosedCharacter(const Character& character, const PosedCharacter& posed, const std::string& path) {
  std::vector<const Mesh*> meshes;
  for (const Mesh& m : character.meshes) meshes.push_back(&m);
  exportPosedMesh(meshes, posed.meshes(), path, &character);
}

}  // namespace mq
