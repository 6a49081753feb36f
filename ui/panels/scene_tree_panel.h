#pragma once
// The scene tree: the character, its meshes, its materials and its bone
// hierarchy. Clicking a bone, mesh or material selects it in the document; the document's selection is
// mirrored back (e.g. after a pick in the viewport).

#include <vector>

#include <QWidget>

class QTreeWidget;
class QTreeWidgetItem;

namespace mq::ui {

class EditorDocument;

class SceneTreePanel : public QWidget {
  Q_OBJECT

 public:
  explicit SceneTreePanel(EditorDocument* document, QWidget* parent = nullptr);
  QTreeWidget* tree() const { return tree_; }
  // The item showing bone `bone` (null when absent), for tests.
  QTreeWidgetItem* boneItem(int bone) const;

 private:
  void rebuild();
  void showSelection();
  void showPoseEdits();
  void onCurrentItemChanged(QTreeWidgetItem* item);

  EditorDocument* document_;
  QTreeWidget* tree_;
  std::vector<QTreeWidgetItem*> boneItems_;
  std::vector<QTreeWidgetItem*> meshItems_;
  std::vector<QTreeWidgetItem*> materialItems_;
  bool syncing_ = false;
};

}  // namespace mq::ui
