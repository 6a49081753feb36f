#include "ui/panels/scene_tree_panel.h"

#include <QHeaderView>
#include <QStyle>
#include <QTreeWidget>
#include <QVBoxLayout>

#include "ui/document/editor_document.h"

namespace mq::ui {
namespace {

enum ItemRole { KindRole = Qt::UserRole + 1, IndexRole };
enum ItemKind { KindNone = 0, KindBone, KindMesh, KindMaterial };

}  // namespace

SceneTreePanel::SceneTreePanel(EditorDocument* document, QWidget* parent)
    : QWidget(parent), document_(document), tree_(new QTreeWidget(this)) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(tree_);
  tree_->setHeaderLabels({tr("Name"), tr("Info")});
  tree_->header()->setSectionResizeMode(0, QHeaderView::Stretch);
  tree_->header()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
  tree_->header()->setStretchLastSection(false);
  tree_->setIndentation(12);
  tree_->setUniformRowHeights(true);

  connect(document_, &EditorDocument::characterReplaced, this, &SceneTreePanel::rebuild);
  connect(document_, &EditorDocument::skeletonChanged, this, &SceneTreePanel::rebuild);
  connect(document_, &EditorDocument::selectionChanged, this, &SceneTreePanel::showSelection);
  connect(document_, &EditorDocument::poseChanged, this, &SceneTreePanel::showPoseEdits);
  connect(tree_, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* item) { onCurrentItemChanged(item); });
  rebuild();
}

QTreeWidgetItem* SceneTreePanel::boneItem(int bone) const {
  return bone >= 0 && bone < static_cast<int>(boneItems_.size()) ? boneItems_[bone] : nullptr;
}

void SceneTreePanel::rebuild() {
  syncing_ = true;
  tree_->clear();
  boneItems_.clear();
  meshItems_.clear();
  materialItems_.clear();
  const Character& character = document_->character();
  const QString name = character.name.empty() ? tr("character") : QString::fromStdString(character.name);
  auto* root = new QTreeWidgetItem(tree_, {name, tr("character")});
  root->setIcon(0, style()->standardIcon(QStyle::SP_DirHomeIcon));

  auto* meshes = new QTreeWidgetItem(root, {tr("Meshes"), QString::number(character.meshes.size())});
  meshes->setIcon(0, style()->standardIcon(QStyle::SP_DirIcon));
  for (size_t i = 0; i < character.meshes.size(); ++i) {
    const Mesh& mesh = character.meshes[i];
    auto* item = new QTreeWidgetItem(meshes, {QString::fromStdString(mesh.name.empty() ? "mesh" : mesh.name),
                                              tr("%1 tris").arg(mesh.triangleCount())});
    item->setIcon(0, style()->standardIcon(QStyle::SP_FileIcon));
    item->setData(0, KindRole, KindMesh);
    item->setData(0, IndexRole, static_cast<int>(i));
    meshItems_.push_back(item);
  }

  if (!character.materials.empty()) {
    auto* materials = new QTreeWidgetItem(root, {tr("Materials"), QString::number(character.materials.size())});
    materials->setIcon(0, style()->standardIcon(QStyle::SP_DirIcon));
    for (size_t i = 0; i < character.materials.size(); ++i) {
      const Material& material = character.materials[i];
      auto* item = new QTreeWidgetItem(
          materials, {QString::fromStdString(material.name), material.textured() ? tr("textured") : QString()});
      item->setData(0, KindRole, KindMaterial);
      item->setData(0, IndexRole, static_cast<int>(i));
      materialItems_.push_back(item);
    }
  }

  const Skeleton& skeleton = character.skeleton;
  auto* bones = new QTreeWidgetItem(root, {tr("Skeleton"), tr("%1 bones").arg(skeleton.boneCount())});
  bones->setIcon(0, style()->standardIcon(QStyle::SP_DirIcon));
  for (int b = 0; b < skeleton.boneCount(); ++b) {
    const Bone& bone = skeleton.bone(b);
    QTreeWidgetItem* parentItem = bone.parent >= 0 ? boneItems_[bone.parent] : bones;
    auto* item = new QTreeWidgetItem(parentItem, {QString::fromStdString(bone.name), QString()});
    item->setData(0, KindRole, KindBone);
    item->setData(0, IndexRole, b);
    boneItems_.push_back(item);
  }
  tree_->expandAll();
  syncing_ = false;
  showPoseEdits();
  showSelection();
}

void SceneTreePanel::showPoseEdits() {
  // Bones with a pose edit are marked, as DCC tools mark keyed channels.
  const PoseEdits& edits = document_->poseEdits();
  for (size_t b = 0; b < boneItems_.size(); ++b) {
    const bool posed = edits.rotations.count(static_cast<int>(b)) > 0;
    if ((boneItems_[b]->text(1) == tr("posed")) != posed) boneItems_[b]->setText(1, posed ? tr("posed") : QString());
  }
}

void SceneTreePanel::showSelection() {
  syncing_ = true;
  QTreeWidgetItem* item = nullptr;
  if (document_->selectedBone() >= 0)
    item = boneItem(document_->selectedBone());
  else if (document_->selectedMesh() >= 0 && document_->selectedMesh() < static_cast<int>(meshItems_.size()))
    item = meshItems_[document_->selectedMesh()];
  else if (document_->selectedMaterial() >= 0 &&
           document_->selectedMaterial() < static_cast<int>(materialItems_.size()))
    item = materialItems_[document_->selectedMaterial()];
  tree_->setCurrentItem(item);
  if (item) tree_->scrollToItem(item);
  syncing_ = false;
}

void SceneTreePanel::onCurrentItemChanged(QTreeWidgetItem* item) {
  if (syncing_ || !item) return;
  const int index = item->data(0, IndexRole).toInt();
  switch (item->data(0, KindRole).toInt()) {
    case KindBone:
      document_->selectBone(index);
      break;
    case KindMesh:
      document_->selectMesh(index);
      break;
    case KindMaterial:
      document_->selectMaterial(index);
      break;
    default:
      document_->selectBone(-1);
      break;
  }
}

}  // namespace mq::ui
