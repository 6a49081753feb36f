#pragma once
// The editor's look: Qt's Fusion style with a dark palette, as DCC tools use,
// so the viewport stands out. Call after QApplication exists.

class QApplication;

namespace mq::ui {

void applyEditorTheme(QApplication& app);

}  // namespace mq::ui
