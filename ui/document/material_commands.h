#pragma once
// One undo step per change to a material (a typed factor, a picked colour,
// a toggled flag).

#include <QString>
#include <QUndoCommand>

#include "core/material/material.h"

namespace mq::ui {

class EditorDocument;

class SetMaterialCommand : public QUndoCommand {
 public:
  SetMaterialCommand(EditorDocument* document, int index, Material after, const QString& what);
  void undo() override;
  void redo() override;

 private:
  EditorDocument* document_;
  int index_;
  Material before_;
  Material after_;
};

}  // namespace mq::ui
