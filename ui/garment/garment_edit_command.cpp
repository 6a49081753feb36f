#include "ui/garment/garment_edit_command.h"

#include "ui/garment/garment_tool.h"

namespace mq::ui {

GarmentEditCommand::GarmentEditCommand(GarmentTool* tool, GarmentScene before, GarmentScene after,
                                       const QString& text, int mergeKey)
    : QUndoCommand(text), tool_(tool), before_(std::move(before)), after_(std::move(after)), mergeKey_(mergeKey) {}

void GarmentEditCommand::undo() { tool_->applyScene(before_); }
void GarmentEditCommand::redo() { tool_->applyScene(after_); }

bool GarmentEditCommand::mergeWith(const QUndoCommand* other) {
  const auto* next = dynamic_cast<const GarmentEditCommand*>(other);
  if (!next || mergeKey_ == 0 || next->mergeKey_ != mergeKey_) return false;
  after_ = next->after_;
  return true;
}

int GarmentEditCommand::nextMergeKey() {
  static int key = 0;
  return ++key;
}

}  // namespace mq::ui
