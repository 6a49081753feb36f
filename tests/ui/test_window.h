#pragma once
// The editor window every GUI test drives: an error dialog fails the test,
// discarding changes is always allowed, and the size is fixed so picks and
// drags land in the same places on every run. Shown; wait for it to be exposed.

#include <QTest>

#include "ui/main_window.h"

namespace mq::ui {

inline MainWindow* makeTestWindow() {
  auto* window = new MainWindow;
  window->reportError = [](const QString& title, const QString& message) {
    QFAIL(qPrintable("unexpected error dialog: " + title + ": " + message));
  };
  window->confirmDiscardChanges = [] { return true; };
  window->resize(1280, 800);
  window->show();
  return window;
}

}  // namespace mq::ui
