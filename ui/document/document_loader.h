#pragma once
// Reading files into a LoadedDocument, off the UI thread. These functions
// touch no widget and may run on a worker thread; they throw mq::Error (or
// std::exception) with a message naming the file and the problem.

#include <QString>

#include "ui/document/editor_document.h"

namespace mq::ui {

// "default" (or empty): the built-in mannequin. A scene document: its
// character, motion and edits. Otherwise a character file (glTF, GLB, FBX, DAE).
LoadedDocument loadDocument(const QString& fileOrDefault);

// A BVH motion retargeted onto `target` by bone names, optionally through a
// name-map file (lines "bvh_joint target_bone"; see core/io/bvh_import.h).
Clip loadMotion(const QString& bvhPath, const Character& target, const QString& nameMapPath = QString());

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
