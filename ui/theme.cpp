#include "ui/theme.h"

#include <QApplication>
#include <QPalette>
#include <QStyleFactory>

namespace mq::ui {

void applyEditorTheme(QApplication& app) {
  app.setStyle(QStyleFactory::create("Fusion"));
  QPalette p;
  const QColor window(0x30, 0x31, 0x34), base(0x24, 0x25, 0x28), text(0xdc, 0xdc, 0xdc);
  const QColor highlight(0x3d, 0x7e, 0xd8);
  p.setColor(QPalette::Window, window);
  p.setColor(QPalette::WindowText, text);
  p.setColor(QPalette::Base, base);
  p.setColor(QPalette::AlternateBase, QColor(0x2b, 0x2c, 0x2f));
  p.setColor(QPalette::ToolTipBase, QColor(0x45, 0x46, 0x4a));
  p.setColor(QPalette::ToolTipText, text);
  p.setColor(QPalette::PlaceholderText, QColor(0x80, 0x80, 0x80));
  p.setColor(QPalette::Text, text);
  p.setColor(QPalette::Button, QColor(0x3a, 0x3b, 0x3f));
  p.setColor(QPalette::ButtonText, text);
  p.setColor(QPalette::BrightText, Qt::white);
  p.setColor(QPalette::Highlight, highlight);
  p.setColor(QPalette::HighlightedText, Qt::white);
  p.setColor(QPalette::Link, highlight.lighter(130));
  p.setColor(QPalette::Mid, QColor(0x28, 0x29, 0x2c));
  p.setColor(QPalette::Dark, QColor(0x1e, 0x1f, 0x21));
  p.setColor(QPalette::Light, QColor(0x48, 0x49, 0x4d));
  const QColor disabled(0x7a, 0x7a, 0x7a);
  p.setColor(QPalette::Disabled, QPalette::WindowText, disabled);
  p.setColor(QPalette::Disabled, QPalette::Text, disabled);
  p.setColor(QPalette::Disabled, QPalette::ButtonText, disabled);
  p.setColor(QPalette::Disabled, QPalette::HighlightedText, disabled);
  app.setPalette(p);
  app.setStyleSheet(
      "QDockWidget::title { background: #26272a; padding: 4px 6px; }"
      "QDockWidget { font-weight: normal; }"
      "QGroupBox { border: 1px solid #45464a; border-radius: 3px; margin-top: 14px; padding-top: 4px; }"
      "QGroupBox::title { subcontrol-origin: margin; left: 8px; padding: 0 3px; color: #a8c4ec; }"
      "QStatusBar { background: #26272a; }"
      "QToolBar { border: none; spacing: 2px; }");
}

}  // namespace mq::ui
