#pragma once
// Every garment edit (a garment added or removed, a measurement, the fabric,
// the integrator, pins) is one of these on the document's undo stack: the
// whole GarmentScene before and after, applied by GarmentTool::applyScene.

#include "ui/document/snapshot_command.h"
#include "ui/garment/garment_scene.h"

namespace mq::ui {

using GarmentEditCommand = SnapshotCommand<GarmentScene>;

}  // namespace mq::ui
