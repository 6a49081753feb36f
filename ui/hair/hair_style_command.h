#pragma once
// Every hairstyle edit (a field, a primitive added, moved or deleted, a
// built-in style picked) is one of these on the document's undo stack: the
// whole style before and after (a few hundred bytes). A change of the scalp
// region (the faces the hair grows from) is one too; applying it re-extracts
// the scalp and regrows the hair.

#include <optional>

#include "core/hair/hairstyle.h"
#include "core/hair/scalp.h"
#include "ui/document/snapshot_command.h"

namespace mq::ui {

// A hairstyle edit's value. nullopt: no hair (adding or removing hair is an
// edit too). live: a step of a drag (the guides regrow; the children wait
// for the drag's last step, which comes with live = false).
struct HairStyleSnapshot {
  std::optional<HairStyle> style;
  bool live = false;
};

using HairStyleCommand = SnapshotCommand<HairStyleSnapshot>;
using HairScalpCommand = SnapshotCommand<ScalpRegion>;

}  // namespace mq::ui
