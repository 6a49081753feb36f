#pragma once
// Every hairstyle edit (a field, a primitive added, moved or deleted, a
// built-in style picked) is one of these on the document's undo stack: the
// whole style before and after (a few hundred bytes). Steps of one drag or of
// one spin box merge into a single command (same non-zero merge key).

#include <optional>

#include <QUndoCommand>

#include "core/hair/hairstyle.h"
#include "core/hair/scalp.h"

namespace mq::ui {

class HairTool;

class HairStyleCommand : public QUndoCommand {
 public:
  // live: a step of a drag (the guides regrow, the children wait for the
  // drag's last step, which comes with live = false).
  // nullopt: no hair (adding hair or removing it is an edit too).
  HairStyleCommand(HairTool* tool, std::optional<HairStyle> before, std::optional<HairStyle> after,
                   const QString& text, int mergeKey = 0, bool live = false);

  void undo() override;
  void redo() override;
  int id() const override { return 0x6861; }
  bool mergeWith(const QUndoCommand* other) override;

  static int nextMergeKey();

 private:
  HairTool* tool_;
  std::optional<HairStyle> before_, after_;
  int mergeKey_;
  bool live_;
};

// A change of the scalp region (the faces the hair grows from): the region
// before and after; applying one re-extracts the scalp and regrows the hair.
// Steps of one spin box merge (same non-zero merge key).
class HairScalpCommand : public QUndoCommand {
 public:
  HairScalpCommand(HairTool* tool, ScalpRegion before, ScalpRegion after, const QString& text, int mergeKey = 0);

  void undo() override;
  void redo() override;
  int id() const override { return 0x6862; }
  bool mergeWith(const QUndoCommand* other) override;

 private:
  HairTool* tool_;
  ScalpRegion before_, after_;
  int mergeKey_;
};

}  // namespace mq::ui
