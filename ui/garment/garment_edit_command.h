#pragma once
// Every garment edit (a garment added or removed, a measurement, the fabric,
// the integrator, pins) is one of these on the document's undo stack: the
// whole GarmentScene before and after. Steps of one spin box merge into a
// single command (same non-zero merge key).

#include <QUndoCommand>

#include "ui/garment/garment_scene.h"

namespace mq::ui {

class GarmentTool;

class GarmentEditCommand : public QUndoCommand {
 public:
  GarmentEditCommand(GarmentTool* tool, GarmentScene before, GarmentScene after, const QString& text,
                     int mergeKey = 0);

  void undo() override;
  void redo() override;
  int id() const override { return 0x6761; }
  bool mergeWith(const QUndoCommand* other) override;

  static int nextMergeKey();

 private:
  GarmentTool* tool_;
  GarmentScene before_, after_;
  int mergeKey_;
};

}  // namespace mq::ui
