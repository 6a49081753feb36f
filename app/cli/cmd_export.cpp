// mannequin-cli export FILE --out OUT.obj|.ply|.gltf|.glb [--clip NAME|INDEX --fps F | --clip rest] [--rigged]
// Without --fps: the rest (bind) pose. With --fps: every frame of the clip,
// one file per frame (OUT_0000.obj, OUT_0001.obj, ...), for other tools.
// --clip rest: the rest pose with the scene's pose edits.
// --rigged: one glTF with the skeleton, the skins and every clip.
// --with garments,hair: one glTF of the scene's take, simulated surfaces baked in.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "app/cli/command.h"
#include "app/cli/scene_take.h"
#include "core/character/posed_character.h"
#include "core/io/file_bytes.h"
#include "core/io/mesh_export.h"
#include "core/io/rigged_export.h"
#include "core/scene/open_scene.h"
#include "core/util/error.h"
#include "core/util/thread_pool.h"
#include "sim/cloth/point_cache.h"

namespace mq::cli {
namespace {

std::string framePath(const std::string& out, int frame) {
  const std::filesystem::path p(out);
  char number[16];
  std::snprintf(number, sizeof number, "_%04d", frame);
  return (p.parent_path() / (p.stem().string() + number + p.extension().string())).string();
}

int exportSequence(const LoadedScene& scene, int clip, double fps, const std::string& out) {
  const Clip& c = scene.character.clips[clip];
  const int frames = static_cast<int>(std::floor(c.duration() * fps + 1e-6)) + 1;
  PosedCharacter posed;
  for (int f = 0; f < frames; ++f) {
    posed.evaluate(scene.character, clip, c.startTime() + static_cast<float>(f / fps), &scene.edits,
                   &ThreadPool::shared());
    exportPosedCharacter(scene.character, posed, framePath(out, f));
  }
  std::cout << "wrote " << frames << " frames of clip '" << c.name << "' to " << framePath(out, 0) << " ...\n";
  return 0;
}

// "garments,hair" -> {"garments", "hair"}
std::vector<std::string> commaSeparated(const std::string& text) {
  std::vector<std::string> parts;
  std::stringstream stream(text);
  for (std::string part; std::getline(stream, part, ',');) parts.push_back(part);
  return parts;
}

void printWarnings(const std::vector<std::string>& warnings, const std::string& out) {
  for (const std::string& w : warnings) std::cerr << "warning: " << out << ": " << w << "\n";
}

TakeRequest takeRequest(const Args& args, const LoadedScene& scene, const std::string& path) {
  TakeRequest request;
  for (const std::string& part : commaSeparated(args.option("--with"))) {
    if (part == "garments")
      request.cloth = true;
    else if (part == "hair")
      request.hair = true;
    else
      throw Error("--with takes garments, hair or both (garments,hair), not '" + part + "'");
  }
  request.fps = float(args.number("--fps", 30.0));
  if (!(request.fps > 0.0f && request.fps <= 1000.0f)) throw Error("--fps must be in (0, 1000]");
  // By default the clip from the document's time to its end; the rest pose: one second.
  const int clip = scene.clipIndex;
  const float seconds = clip >= 0 ? scene.character.clips[clip].endTime() - scene.document.time : 1.0f;
  const double frames = args.number("--frames", std::max(1.0, std::floor(double(seconds) * request.fps)));
  if (!(frames >= 1 && frames <= 100000) || frames != std::floor(frames))
    throw Error("--frames expects a whole number from 1 to 100000");
  request.frames = int(frames);
  const std::string strands = args.option("--hair-strands", "guides");
  if (strands == "guides")
    request.hairStrands = -1;
  else if (strands == "all")
    request.hairStrands = 0;
  else {
    const double n = args.number("--hair-strands", 0);
    if (!(n >= 1) || n != std::floor(n)) throw Error("--hair-strands expects guides, all or a positive whole number");
    request.hairStrands = long(n);
  }
  return request;
}

// --point-cache DIR/NAME.pc2|.mdd: per baked surface NAME_<surface>.pc2 (or
// .mdd) with every frame, and NAME_<surface>.obj, the mesh it deforms.
void writePointCaches(const std::vector<BakedSurface>& surfaces, const std::string& path, float fps) {
  const std::string ext = fileExtension(path);
  if (ext != "pc2" && ext != "mdd") throw Error("--point-cache writes .pc2 or .mdd files: " + path);
  const std::vector<std::string> stems = cloth::writeSurfacePointCaches(surfaces, path, fps);
  for (size_t i = 0; i < stems.size(); ++i)
    std::cout << "wrote " << stems[i] << "." << ext << " and " << stems[i] << ".obj (" << surfaces[i].name << ", "
              << surfaces[i].frames.size() << " frames of " << surfaces[i].frames.front().size() / 3 << " points)\n";
}

// export SCENE --with garments,hair: the character rigged, playing the
// scene's clip, with the simulated garments and hair as baked surfaces.
int exportTake(const Args& args, LoadedScene& scene, const std::string& path, const std::string& out) {
  const std::string caches = args.option("--point-cache");
  if (out.empty() && caches.empty())
    throw Error("--with needs --out OUT.glb|OUT.gltf, --point-cache OUT.pc2|OUT.mdd or both");
  if (!out.empty() && !isRiggedExportPath(out)) throw Error("--with writes glTF: use --out OUT.gltf or OUT.glb");
  if (!isSceneDocumentPath(path)) throw FileError(path, "--with needs a scene document (.mqscene or .json)");
  scene.clipIndex = clipOption(args, scene, path);
  const TakeRequest request = takeRequest(args, scene, path);
  RiggedExportOptions options;
  const int clip = scene.clipIndex;
  options.take = ExportTake{clip >= 0 ? scene.character.clips[clip].name : "rest",
                            clip,
                            takeFrameTime(scene, 0, request.fps),
                            request.fps,
                            request.frames,
                            &scene.edits};
  options.baked = recordSceneTake(scene, path, request);
  if (!caches.empty()) writePointCaches(options.baked, caches, request.fps);
  if (out.empty()) return 0;
  printWarnings(exportRiggedCharacter(scene.character, out, options), out);
  std::cout << "wrote " << out << " (" << request.frames << " frames at " << request.fps << " fps of "
            << clipLabel(scene, clip) << ": " << scene.character.skeleton.boneCount() << " bones"
            << withHelperBones(scene.character);
  for (const BakedSurface& s : options.baked)
    std::cout << ", " << s.name << " (" << s.frames.front().size() / 3 << " vertices)";
  std::cout << ")\n";
  return 0;
}

int runExport(const std::vector<std::string>& argv) {
  const Args args(argv);
  args.allowOnly({"--out", "--clip", "--fps", "--skinning", "--helper-bones", "--regenerate-weights",
                  "--smooth-weights", "--scale", "--auto-rig", "--rigged", "--with", "--frames", "--hair-strands",
                  "--point-cache"});
  if (args.positional().size() != 1) throw Error("export needs exactly one FILE");
  const std::string out = args.option("--out");
  if ((out.empty() && !args.has("--with")) || (!out.empty() && !isMeshExportPath(out)))
    throw Error("export needs --out OUT.obj, .ply, .gltf or .glb");
  if (args.has("--point-cache") && !args.has("--with"))
    throw Error("--point-cache writes simulated surfaces: it goes with --with garments,hair");
  LoadedScene scene = openScene(args.positional()[0]);
  printMotionMatch(scene);
  applyCharacterOptions(args, scene);
  applySkinningOption(args, scene);
  if (args.has("--with")) return exportTake(args, scene, args.positional()[0], out);  // a sheet needs no character
  if (scene.character.meshes.empty())
    throw Error("'" + (scene.character.name.empty() ? args.positional()[0] : scene.character.name) +
                "' has no meshes to write (a BVH holds a skeleton and motion only: "
                "apply it to a character with pose FILE --motion BVH)");

  if (args.has("--frames") || args.has("--hair-strands"))
    throw Error("--frames and --hair-strands go with --with garments,hair");
  if (args.has("--rigged")) {
    if (!isRiggedExportPath(out)) throw Error("--rigged writes glTF: use --out OUT.gltf or OUT.glb");
    if (args.has("--clip")) throw Error("--rigged writes every clip; --clip does not apply");
    const double fps = args.number("--fps", 30.0);
    printWarnings(exportRiggedCharacter(scene.character, out, static_cast<float>(fps)), out);
    std::cout << "wrote " << out << " (rigged: " << scene.character.skeleton.boneCount() << " bones"
              << withHelperBones(scene.character) << ", " << scene.character.clips.size() << " clips sampled at " << fps
              << " fps)\n";
    return 0;
  }
  if (args.option("--clip") == "rest") {
    // The rest pose with the document's pose edits, as render --clip rest shows it.
    if (args.has("--fps")) throw Error("--clip rest is one pose: it takes no --fps");
    PosedCharacter posed;
    posed.evaluate(scene.character, -1, 0.0f, &scene.edits, &ThreadPool::shared());
    exportPosedCharacter(scene.character, posed, out);
    std::cout << "wrote " << out << " (rest pose with " << scene.edits.rotations.size() << " pose edits)\n";
    return 0;
  }
  if (!args.has("--fps")) {
    if (args.has("--clip")) throw Error("--clip needs --fps (export writes one file per frame), or is rest");
    PosedCharacter posed;
    posed.evaluate(scene.character, -1, 0.0f, nullptr, &ThreadPool::shared());
    exportPosedCharacter(scene.character, posed, out);
    std::cout << "wrote " << out << " (rest pose)\n";
    return 0;
  }
  const double fps = args.number("--fps", 24.0);
  if (!(fps > 0.0 && fps <= 1000.0)) throw Error("--fps must be in (0, 1000]");
  int clip = scene.clipIndex;
  if (args.has("--clip")) clip = scene.character.findClip(args.option("--clip"));
  if (clip < 0) throw Error("'" + scene.character.name + "' has no such clip");
  return exportSequence(scene, clip, fps, out);
}

static Registration reg(
    {"export",
     "FILE --out OUT.obj|.ply|.gltf|.glb [--clip NAME|INDEX --fps F | --clip rest] [--skinning lbs|dqs|cones]\n"
     "         [--helper-bones] [--regenerate-weights] [--smooth-weights] [--scale S] [--auto-rig] [--rigged [--fps "
     "F]]\n"
     "         [--with garments,hair [--clip C] [--frames N] [--fps F] [--hair-strands guides|all|N]\n"
     "          [--point-cache OUT.pc2|OUT.mdd]]",
     "write the rest pose, or every frame of a clip (OUT_0000.obj ...), as meshes; --rigged: the\n"
     "skeleton, skins, materials and every clip (sampled at F fps, 30 by default) as one glTF or GLB;\n"
     "--with (a scene document): the character playing its clip from the document's time for N frames\n"
     "at F fps, its garments and/or hair simulated as simulate does and stored as per-frame morph targets;\n"
     "--point-cache: each simulated surface as a PC2 or MDD point cache beside an OBJ of the mesh it deforms",
     runExport});

}  // namespace
}  // namespace mq::cli
