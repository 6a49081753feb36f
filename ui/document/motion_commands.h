#pragma once
// Applying a BVH motion as one undo step: the clip is added and made
// current, and the scene document records the file (so a saved scene applies
// it again); undo removes the clip and brings back the clip, time and motion
// record from before.

#include <string>

#include <QUndoCommand>

#include "core/character/character.h"

namespace mq::ui {

class EditorDocument;

// The scene document's "motion" section.
struct MotionRecord {
  std::string file;
  std::string map;
  bool inPlace = false;
};

class ApplyMotionCommand : public QUndoCommand {
 public:
  ApplyMotionCommand(EditorDocument* document, Clip clip, MotionRecord after);
  void undo() override;
  void redo() override;

 private:
  EditorDocument* document_;
  Clip clip_;
  MotionRecord before_;
  MotionRecord after_;
  int clipBefore_;
  float timeBefore_;
};

}  // namespace mq::ui
