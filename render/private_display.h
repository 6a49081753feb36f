#pragma once
// Debian's VTK renders only through X, even offscreen. ensureDisplay() makes
// sure an X server answers: the one in $DISPLAY when there is one, otherwise
// a private Xvfb started on a free display number (Xvfb -displayfd picks it),
// with DISPLAY pointed at it for the rest of the process. The private server
// stops when the process exits (and dies with it if the process crashes).

#include <string>

namespace mq::render {

// Returns the display in use (e.g. ":0" or ":99"). Throws mq::Error saying
// how to fix it when no X server answers and Xvfb cannot be started.
std::string ensureDisplay();

// True when ensureDisplay() started its own Xvfb.
bool usingPrivateDisplay();

}  // namespace mq::render
