#include "ui/jobs/step_progress.h"

#include <QCoreApplication>

namespace mq::ui {

StepProgress::StepProgress(QWidget* parent, const QString& text, int minimumMs)
    : dialog_(text, QObject::tr("Cancel"), 0, 100, parent) {
  dialog_.setWindowModality(Qt::WindowModal);
  dialog_.setMinimumDuration(minimumMs);
}

void StepProgress::step(int done, int total) {
  dialog_.setMaximum(total);
  dialog_.setValue(done);
  QCoreApplication::processEvents();
}

}  // namespace mq::ui
