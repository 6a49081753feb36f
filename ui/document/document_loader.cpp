#include "ui/document/document_loader.h"

#include <QFileInfo>

#include "core/io/bvh_import.h"
#include "core/scene/open_scene.h"
#include "core/scene/scene_document.h"

namespace mq::ui {
namespace {

QString suffixOf(const QString& path) { return QFileInfo(path).suffix().toLower(); }

}  // namespace

LoadedDocument loadDocument(const QString& fileOrDefault) {
  const QString file = fileOrDefault.isEmpty() ? QString("default") : fileOrDefault;
  LoadedScene scene = openScene(file.toStdString());
  LoadedDocument out;
  out.character = std::move(scene.character);
  out.scene = std::move(scene.document);
  out.edits = std::move(scene.edits);
  out.clipIndex = scene.clipIndex;
  out.fileMaterials = std::move(scene.fileMaterials);
  out.fileSkins = std::move(scene.fileSkins);
  if (file == "default") {
    out.displayName = "default mannequin";
  } else {
    out.displayName = QFileInfo(file).fileName();
    if (!scene.documentPath.empty()) out.documentPath = QFileInfo(file).absoluteFilePath();
    // A character file: keep its absolute path (saving makes it relative).
    else
      out.scene.character = QFileInfo(file).absoluteFilePath().toStdString();
  }
  return out;
}

LoadedMotion loadMotion(const QString& bvhPath, const Character& target, const QString& nameMapPath, bool inPlace) {
  LoadedMotion out;
  out.motion = retargetBvhMotion(bvhPath.toStdString(), target, {nameMapPath.toStdString(), inPlace});
  out.bvhPath = QFileInfo(bvhPath).absoluteFilePath();
  out.nameMapPath = nameMapPath.isEmpty() ? QString() : QFileInfo(nameMapPath).absoluteFilePath();
  out.inPlace = inPlace;
  return out;
}

bool isMotionFile(const QString& path) { return suffixOf(path) == "bvh"; }
bool isSceneFile(const QString& path) { return isSceneDocumentPath(path.toStdString()); }
bool isCharacterFile(const QString& path) {
  static const QStringList kinds = {"gltf", "glb", "fbx", "dae"};
  return kinds.contains(suffixOf(path));
}
bool isOpenableFile(const QString& path) { return isMotionFile(path) || isSceneFile(path) || isCharacterFile(path); }

QString openFileFilter() {
  return QObject::tr(
      "All supported (*.mqscene *.json *.gltf *.glb *.fbx *.dae *.bvh);;"
      "Scene documents (*.mqscene *.json);;"
      "Characters (*.gltf *.glb *.fbx *.dae);;"
      "Motions (*.bvh);;All files (*)");
}
QString saveSceneFilter() { return QObject::tr("Scene documents (*.mqscene)"); }
QString motionFilter() { return QObject::tr("Motions (*.bvh)"); }
QString nameMapFilter() { return QObject::tr("Bone-name maps (*.txt *.map);;All files (*)"); }
QString exportMeshFilter() { return QObject::tr("Wavefront OBJ (*.obj);;Stanford PLY (*.ply)"); }

}  // namespace mq::ui
