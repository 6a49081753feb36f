#include "ui/document/snapshot_command.h"

namespace mq::ui {

int nextUndoMergeKey() {
  static int key = 0;
  return ++key;
}

}  // namespace mq::ui
