#include "ui/document/document_loader.h"

#include <QFileInfo>

#include "core/character/default_mannequin.h"
#include "core/io/bvh_import.h"
#include "core/io/character_import.h"
#include "core/scene/scene_document.h"

namespace mq::ui {
namespace {

QString suffixOf(const QString& path) { return QFileInfo(path).suffix().toLower(); }

Character characterOfScene(const SceneDocument& scene, const std::string& documentPath) {
  if (!scene.hasCharacter()) return Character{};
  if (scene.character == "default") return makeDefaultMannequin();
  return importCharacter(resolveDocumentPath(documentPath, scene.character));
}

LoadedDocument loadSceneFile(const QString& path) {
  const std::string file = path.toStdString();
  LoadedDocument out;
  out.scene = loadSceneDocument(file);
  out.character = characterOfScene(out.scene, file);
  if (!out.scene.motionFile.empty()) {
    const std::string motion = resolveDocumentPath(file, out.scene.motionFile);
    const std::string map =
        out.scene.motionMapFile.empty() ? std::string() : resolveDocumentPath(file, out.scene.motionMapFile);
    out.character.clips.push_back(importBvhMotion(motion, out.character, map));
  }
  out.documentPath = QFileInfo(path).absoluteFilePath();
  out.displayName = QFileInfo(path).fileName();
  return out;
}

}  // namespace

LoadedDocument loadDocument(const QString& fileOrDefault) {
  if (fileOrDefault.isEmpty() || fileOrDefault == "default") {
    LoadedDocument out;
    out.character = makeDefaultMannequin();
    out.displayName = "default mannequin";
    return out;
  }
  if (isSceneFile(fileOrDefault)) return loadSceneFile(fileOrDefault);
  LoadedDocument out;
  out.character = importCharacter(fileOrDefault.toStdString());
  out.scene.character = QFileInfo(fileOrDefault).absoluteFilePath().toStdString();
  out.displayName = QFileInfo(fileOrDefault).fileName();
  return out;
}

Clip loadMotion(const QString& bvhPath, const Character& target) {
  return importBvhMotion(bvhPath.toStdString(), target);
}

bool isMotionFile(const QString& path) { return suffixOf(path) == "bvh"; }
bool isSceneFile(const QString& path) { return isSceneDocumentPath(path.toStdString()); }
bool isCharacterFile(const QString& path) {
  static const QStringList kinds = {"gltf", "glb", "fbx", "dae"};
  return kinds.contains(suffixOf(path));
}
bool isOpenableFile(const QString& path) {
  return isMotionFile(path) || isSceneFile(path) || isCharacterFile(path);
}

QString openFileFilter() {
  return QObject::tr("All supported (*.mqscene *.json *.gltf *.glb *.fbx *.dae *.bvh);;"
                     "Scene documents (*.mqscene *.json);;"
                     "Characters (*.gltf *.glb *.fbx *.dae);;"
                     "Motions (*.bvh);;All files (*)");
}
QString saveSceneFilter() { return QObject::tr("Scene documents (*.mqscene)"); }
QString exportMeshFilter() { return QObject::tr("Wavefront OBJ (*.obj);;Stanford PLY (*.ply)"); }

}  // namespace mq::ui
