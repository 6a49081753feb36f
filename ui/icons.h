#pragma once
// Toolbar and timeline icons drawn with QPainter in the light-on-dark style
// of the theme (no image resources to ship, crisp at any device pixel ratio).

#include <QIcon>

namespace mq::ui {

enum class Icon { New, Open, Save, Undo, Redo, FrameAll, Skeleton, Play, Pause, ToStart, ToEnd, StepBack, StepForward };

QIcon makeIcon(Icon icon);

}  // namespace mq::ui
