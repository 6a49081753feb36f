#pragma once
// A modal progress dialog for a job the GUI thread runs in steps (a hair
// bake, a weight rebuild): step() moves it and lets the events through, so
// the window repaints and Cancel can be pressed; the job polls cancelled().

#include <QProgressDialog>

namespace mq::ui {

class StepProgress {
 public:
  // Shown once the job has run `minimumMs` and is not nearly done.
  StepProgress(QWidget* parent, const QString& text, int minimumMs);

  void step(int done, int total);
  bool cancelled() const { return dialog_.wasCanceled(); }
  QProgressDialog& dialog() { return dialog_; }

 private:
  QProgressDialog dialog_;
};

}  // namespace mq::ui
