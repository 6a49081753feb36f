// mannequin-cli pose FILE --time T [--clip NAME|INDEX] [--motion BVH [--map MAP] [--in-place]] --out
// OUT.obj|.ply|.gltf|.glb Writes the character posed at time T (on the clip's own key-time axis) in world space. A
// motion prints how its joints were paired with the bones.
#include <iostream>

#include <nlohmann/json.hpp>

#include "app/cli/command.h"
#include "core/character/posed_character.h"
#include "core/io/mesh_export.h"
#include "core/scene/open_scene.h"
#include "core/util/atomic_file.h"
#include "core/util/error.h"
#include "core/util/thread_pool.h"

namespace mq::cli {
namespace {

// The clip the options ask for: --motion adds one and plays it, --clip
// picks one, otherwise the scene's current clip.
int chooseClip(const Args& args, LoadedScene& scene) {
  if (args.has("--motion")) {
    BoneMatchReport match;
    scene.clipIndex =
        addMotion(scene.character, args.option("--motion"), {args.option("--map"), args.has("--in-place")}, &match);
    printMotionMatch(args.option("--motion"), match);
  } else if (args.has("--map") || args.has("--in-place")) {
    throw Error(std::string(args.has("--map") ? "--map" : "--in-place") + " needs --motion");
  }
  return clipOption(args, scene, args.positional()[0]);
}

// {"bones": [{"name", "head": [x, y, z]}]}: each bone's world-space origin.
void writeJoints(const Skeleton& skeleton, const std::vector<glm::mat4>& worldFromBone, const std::string& path) {
  nlohmann::json bones = nlohmann::json::array();
  for (int b = 0; b < skeleton.boneCount(); ++b) {
    const glm::vec3 head(worldFromBone[b][3]);
    bones.push_back({{"name", skeleton.bone(b).name}, {"head", {head.x, head.y, head.z}}});
  }
  const std::string text = nlohmann::json{{"bones", bones}}.dump(2) + "\n";
  writeFileAtomically(path, [&](std::ostream& out) { out << text; });
}

int runPose(const std::vector<std::string>& argv) {
  const Args args(argv);
  args.allowOnly({"--time", "--clip", "--motion", "--map", "--in-place", "--out", "--skinning", "--helper-bones",
                  "--regenerate-weights", "--smooth-weights", "--joints-out", "--scale", "--auto-rig"});
  if (args.positional().size() != 1) throw Error("pose needs exactly one FILE");
  const std::string out = args.option("--out");
  if (out.empty()) throw Error("pose needs --out OUT.obj, .ply, .gltf or .glb");
  if (!isMeshExportPath(out)) throw Error("--out must end in .obj, .ply, .gltf or .glb: " + out);

  LoadedScene scene = openScene(args.positional()[0]);
  printMotionMatch(scene);
  applyCharacterOptions(args, scene);
  applySkinningOption(args, scene);
  if (scene.character.meshes.empty())
    throw Error("'" + scene.character.name +
                "' has no meshes to write (a BVH holds a skeleton and motion only: "
                "apply it to a character with pose FILE --motion BVH)");
  const int clip = chooseClip(args, scene);
  const float time = static_cast<float>(args.number("--time", scene.document.time));
  PosedCharacter posed;
  posed.evaluate(scene.character, clip, time, &scene.edits, &ThreadPool::shared());
  exportPosedCharacter(scene.character, posed, out);
  if (args.has("--joints-out"))
    writeJoints(scene.character.skeleton, posed.worldFromBone(), args.option("--joints-out"));
  std::cout << "wrote " << out << ": " << scene.character.vertexCount() << " vertices, "
            << scene.character.triangleCount() << " triangles, clip "
            << (clip >= 0 ? "'" + scene.character.clips[clip].name + "'" : std::string("none (rest pose)"))
            << " at t = " << time << " s, " << skinningMethodName(scene.character.skinning) << " skinning"
            << withHelperBones(scene.character) << "\n";
  return 0;
}

static Registration reg({"pose",
                         "FILE --time T [--clip NAME|INDEX|rest] [--motion BVH [--map MAP] [--in-place]]\n"
                         "         --out OUT.obj|.ply|.gltf|.glb [--skinning lbs|dqs|cones] [--helper-bones] "
                         "[--regenerate-weights] [--smooth-weights]\n"
                         "         [--scale S] [--auto-rig] [--joints-out JOINTS.json]",
                         "write the posed mesh at time T in world space (OBJ, PLY, glTF or GLB)", runPose,
                         "--motion applies a BVH to the character: its joints drive the bones of the same name,\n"
                         "then of the same humanoid role; --map MAP pairs them by a file of 'bvh_joint bone' lines\n"
                         "first. Prints 'matched N of M bones; unmatched: ...' on stderr. --in-place drops the\n"
                         "root's horizontal travel (a walk stays on the spot)."});

}  // namespace
}  // namespace mq::cli
