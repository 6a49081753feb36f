#pragma once
// An undo step that holds a whole value before and after an edit (a garment
// scene, a hairstyle, a scalp region: small enough to copy) and the setter
// that applies one. Steps pushed with the same non-zero merge key (the steps
// of one drag or of one spin box) merge into a single step.

#include <functional>
#include <utility>

#include <QUndoCommand>

namespace mq::ui {

// A merge key for the steps of one gesture, unique across all snapshot commands.
int nextUndoMergeKey();

template <class Value>
class SnapshotCommand : public QUndoCommand {
 public:
  using Apply = std::function<void(const Value&)>;

  SnapshotCommand(Apply apply, Value before, Value after, const QString& text, int mergeKey = 0)
      : QUndoCommand(text),
        apply_(std::move(apply)),
        before_(std::move(before)),
        after_(std::move(after)),
        mergeKey_(mergeKey) {}

  void undo() override { apply_(before_); }
  void redo() override { apply_(after_); }
  int id() const override { return kId; }
  bool mergeWith(const QUndoCommand* other) override {
    const auto* next = dynamic_cast<const SnapshotCommand*>(other);
    if (!next || mergeKey_ == 0 || next->mergeKey_ != mergeKey_) return false;
    after_ = next->after_;
    return true;
  }

  static int nextMergeKey() { return nextUndoMergeKey(); }

 private:
  static constexpr int kId = 0x736e;  // QUndoStack tries mergeWith only between equal ids
  Apply apply_;
  Value before_, after_;
  int mergeKey_;
};

}  // namespace mq::ui
