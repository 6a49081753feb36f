#include "ui/hair/hair_style_command.h"

#include "ui/hair/hair_tool.h"

namespace mq::ui {

HairStyleCommand::HairStyleCommand(HairTool* tool, std::optional<HairStyle> before, std::optional<HairStyle> after,
                                   const QString& text, int mergeKey, bool live)
    : QUndoCommand(text), tool_(tool), before_(std::move(before)), after_(std::move(after)), mergeKey_(mergeKey),
      live_(live) {}

void HairStyleCommand::undo() { tool_->applyStyle(before_, false); }
void HairStyleCommand::redo() { tool_->applyStyle(after_, live_); }

bool HairStyleCommand::mergeWith(const QUndoCommand* other) {
  const auto* next = dynamic_cast<const HairStyleCommand*>(other);
  if (!next || mergeKey_ == 0 || next->mergeKey_ != mergeKey_) return false;
  after_ = next->after_;
  live_ = next->live_;
  return true;
}

int HairStyleCommand::nextMergeKey() {
  static int key = 0;
  return ++key;
}

HairScalpCommand::HairScalpCommand(HairTool* tool, ScalpRegion before, ScalpRegion after, const QString& text,
                                   int mergeKey)
    : QUndoCommand(text), tool_(tool), before_(std::move(before)), after_(std::move(after)), mergeKey_(mergeKey) {}

void HairScalpCommand::undo() { tool_->applyScalp(before_); }
void HairScalpCommand::redo() { tool_->applyScalp(after_); }

bool HairScalpCommand::mergeWith(const QUndoCommand* other) {
  const auto* next = dynamic_cast<const HairScalpCommand*>(other);
  if (!next || mergeKey_ == 0 || next->mergeKey_ != mergeKey_) return false;
  after_ = next->after_;
  return true;
}

}  // namespace mq::ui
