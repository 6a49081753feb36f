#pragma once
// What `mannequin` does from its command line once the file is open: set up
// the view, script the garment tool (documentation pictures, test scenes),
// save, and take a screenshot and quit. The editor's main only parses the
// options into a ScriptedSession.

#include <QString>
#include <QStringList>

namespace mq::ui {

class MainWindow;

struct ScriptedSession {
  QString clip;  // a clip name, or "rest"
  bool setTime = false;
  double time = 0.0;        // seconds into the clip
  QString select;           // a bone, material or mesh
  QStringList addGarments;  // "tshirt", "skirt", "trousers"
  int bakes = 0;            // each --bake-garments bakes once more
  QString exportBakeDir;
  int simulateSteps = 0;
  bool showStretch = false;
  bool showPattern = false;  // the current garment's pattern dock
  QString hairBrush;         // a grooming brush chosen in the Hair dock ("comb", ...)
  QString saveAs;
  QString screenshot;  // empty: stay open

  bool takesScreenshot() const { return !screenshot.isEmpty(); }
  // Runs once, when `window` has opened the first file (`loaded`: whether it could).
  void run(MainWindow& window, bool loaded) const;
};

}  // namespace mq::ui
