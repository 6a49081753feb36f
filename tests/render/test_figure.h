#pragma once
// A small rigged figure owned by the render tests: ellipsoid body parts bound
// rigidly to a humanoid skeleton (the default mannequin's bone names), with an
// "arm_raise" clip. It keeps the baseline images independent of changes to
// the default mannequin.

#include "core/character/character.h"

namespace mq::test {

Character makeTestFigure();

}  // namespace mq::test
