#pragma once
// A viewport tool's event filter body: the mouse press, move and release go
// to the tool's handlers (each returns true when it used the event); other
// events pass on.

#include <QEvent>
#include <QMouseEvent>

namespace mq::ui {

template <class Tool>
bool routeMouseEvent(Tool* tool, QEvent* event, bool (Tool::*press)(QMouseEvent*), bool (Tool::*move)(QMouseEvent*),
                     bool (Tool::*release)(QMouseEvent*)) {
  // Cast only once the type is known: any other event is not a QMouseEvent
  // (UBSan's vptr check caught the cast done up front).
  auto mouse = [event] { return static_cast<QMouseEvent*>(event); };
  switch (event->type()) {
    case QEvent::MouseButtonPress:
      return (tool->*press)(mouse());
    case QEvent::MouseMove:
      return (tool->*move)(mouse());
    case QEvent::MouseButtonRelease:
      return (tool->*release)(mouse());
    default:
      return false;
  }
}

}  // namespace mq::ui
