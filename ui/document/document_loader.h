#pragma once
// Reading files into a LoadedDocument, off the UI thread. These functions
// touch no widget and may run on a worker thread; they throw mq::Error (or
// std::exception) with a message naming the file and the problem.

#include <QString>

#include "core/io/bvh_import.h"
#include "ui/document/editor_document.h"

namespace mq::ui {

// "default" (or empty): the built-in mannequin. A scene document: its
// character, motion and edits. Otherwise a character file (glTF, GLB, FBX, DAE).
LoadedDocument loadDocument(const QString& fileOrDefault);

// A BVH motion retargeted onto a character, and the choices that made it.
struct LoadedMotion {
  RetargetedMotion motion;  // the clip and how joints were paired with bones
  QString bvhPath;          // absolute
  QString nameMapPath;      // absolute, empty for none
  bool inPlace = false;
};

// A BVH motion retargeted onto `target` by bone names and humanoid roles,
// through a name-map file first when given (lines "bvh_joint target_bone";
// see core/io/bone_match.h); `inPlace` drops the root's horizontal travel.
LoadedMotion loadMotion(const QString& bvhPath, const Character& target, const QString& nameMapPath = QString(),
                        bool inPlace = false);

// File kinds by extension.
bool isMotionFile(const QString& path);
bool isSceneFile(const QString& path);
bool isCharacterFile(const QString& path);
bool isOpenableFile(const QString& path);
// Filter strings for QFileDialog.
QString openFileFilter();
QString saveSceneFilter();
QString exportMeshFilter();
QString motionFilter();
QString nameMapFilter();

}  // namespace mq::ui
