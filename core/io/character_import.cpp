#include "core/io/character_import.h"

#include "core/io/assimp_import.h"
#include "core/io/bvh_import.h"
#include "core/io/file_bytes.h"
#include "core/io/gltf_reader.h"
#include "core/util/error.h"

namespace mq {

Character importCharacter(const std::string& path) {
  const std::string ext = fileExtension(path);
  // A missing, unreadable or empty file fails here, whatever its type.
  if (readFileBytes(path).empty()) throw FileError(path, "empty file");
  if (ext == "gltf" || ext == "glb") return readGltfCharacter(path);
  if (ext == "fbx" || ext == "dae") return importWithAssimp(path);
  if (ext == "bvh") return loadBvhCharacter(path);
  if (ext == "obj" || ext == "ply" || ext == "stl") return importWithAssimp(path);  // static meshes
  throw FileError(path,
                  "unsupported file type '." + ext + "' (expected .gltf, .glb, .fbx, .dae, .bvh, .obj, .ply or .stl)");
}

}  // namespace mq
