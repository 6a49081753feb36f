#pragma once
// File > Apply Motion: one dialog to choose a BVH motion, see its skeleton
// beside the character's with the joints paired automatically (same name,
// then same humanoid role), optionally choose a bone-name map that overrides
// the pairing, turn the root's travel on or off, and apply. Unmatched bones
// on either side are highlighted, so a motion that would move only part of
// the character says so before it is applied.

#include <optional>

#include <QDialog>

#include "core/character/character.h"
#include "core/io/bone_match.h"

class QCheckBox;
class QDialogButtonBox;
class QGridLayout;
class QLabel;
class QLineEdit;
class QPushButton;
class QTreeWidget;

namespace mq::ui {

class ApplyMotionDialog : public QDialog {
  Q_OBJECT

 public:
  // `character`'s skeleton is copied; the dialog never changes the document.
  explicit ApplyMotionDialog(const Character& character, QWidget* parent = nullptr);

  // Reads the BVH and pairs its joints again (on the calling thread: a BVH
  // of thousands of frames reads in a fraction of a second).
  void setMotionFile(const QString& bvhPath);
  // Empty: no map.
  void setNameMapFile(const QString& mapPath);

  QString motionFile() const;
  QString nameMapFile() const;
  bool inPlace() const;  // root motion off
  // The pairing shown; none while no BVH is chosen or it cannot be read.
  const std::optional<BoneMatchReport>& report() const { return report_; }

  // For tests and screenshots.
  QTreeWidget* motionTree() const { return motionTree_; }
  QTreeWidget* characterTree() const { return characterTree_; }
  QLabel* summaryLabel() const { return summary_; }
  QCheckBox* rootMotionBox() const { return rootMotion_; }
  QPushButton* applyButton() const { return apply_; }

 private:
  QGridLayout* makeFileRows();
  void browseMotion();
  void browseNameMap();
  void rematch();
  void showProblem(const QString& message);
  void fillMotionTree();
  void fillCharacterTree();

  Skeleton character_;
  QString characterName_;
  std::optional<Skeleton> motion_;
  std::optional<BoneMatchReport> report_;
  QLineEdit* motionPath_;
  QLineEdit* mapPath_;
  QLabel* summary_;
  QTreeWidget* motionTree_;
  QTreeWidget* characterTree_;
  QCheckBox* rootMotion_;
  QDialogButtonBox* buttons_;
  QPushButton* apply_ = nullptr;
};

}  // namespace mq::ui
