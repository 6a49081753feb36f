#include "ui/document/motion_commands.h"

#include <QCoreApplication>

#include "ui/document/editor_document.h"

namespace mq::ui {
namespace {

MotionRecord recordOf(const SceneDocument& scene) {
  return {scene.motionFile, scene.motionMapFile, scene.motionInPlace};
}

void store(const MotionRecord& record, SceneDocument& scene) {
  scene.motionFile = record.file;
  scene.motionMapFile = record.map;
  scene.motionInPlace = record.inPlace;
}

}  // namespace

ApplyMotionCommand::ApplyMotionCommand(EditorDocument* document, Clip clip, MotionRecord after)
    : document_(document),
      clip_(std::move(clip)),
      before_(recordOf(document->sceneSections())),
      after_(std::move(after)),
      clipBefore_(document->clipIndex()),
      timeBefore_(document->time()) {
  setText(QCoreApplication::translate("mq", "Apply motion %1").arg(QString::fromStdString(clip_.name)));
}

void ApplyMotionCommand::redo() {
  store(after_, document_->sceneSections());
  document_->addClip(clip_);
}

void ApplyMotionCommand::undo() {
  store(before_, document_->sceneSections());
  document_->removeLastClip(clipBefore_, timeBefore_);
}

}  // namespace mq::ui
