#include "ui/motion/apply_motion_dialog.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSplitter>
#include <QTreeWidget>
#include <QVBoxLayout>

#include "core/io/bvh_import.h"
#include "ui/document/document_loader.h"

namespace mq::ui {
namespace {

// Unmatched rows stand out on the dark theme and on a light one alike.
void highlightUnmatched(QTreeWidgetItem* item) {
  for (int c = 0; c < item->columnCount(); ++c) {
    item->setBackground(c, QColor(150, 90, 20));
    item->setForeground(c, QColor(255, 255, 255));
  }
  item->setToolTip(0, QObject::tr("Not matched: this bone will not move with the motion"));
}

QTreeWidget* makeTree(const QStringList& headers) {
  auto* tree = new QTreeWidget;
  tree->setHeaderLabels(headers);
  tree->setUniformRowHeights(true);
  tree->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
  tree->setSelectionMode(QAbstractItemView::NoSelection);
  return tree;
}

QString lastDirectory() { return QSettings().value("lastDirectory").toString(); }

}  // namespace

ApplyMotionDialog::ApplyMotionDialog(const Character& character, QWidget* parent)
    : QDialog(parent),
      character_(character.skeleton),
      characterName_(QString::fromStdString(character.name)),
      motionPath_(new QLineEdit),
      mapPath_(new QLineEdit),
      summary_(new QLabel),
      motionTree_(makeTree({tr("Motion joint"), tr("Drives"), tr("Matched by")})),
      characterTree_(makeTree({tr("Character bone"), tr("Driven by")})),
      rootMotion_(new QCheckBox(tr("Root motion: the character travels with the motion (off: in place)"))),
      buttons_(new QDialogButtonBox(QDialogButtonBox::Cancel)) {
  setWindowTitle(tr("Apply Motion"));
  auto* trees = new QSplitter;
  trees->addWidget(motionTree_);
  trees->addWidget(characterTree_);
  trees->setSizes({620, 360});  // the motion side has the extra "Matched by" column
  summary_->setWordWrap(true);
  summary_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  rootMotion_->setChecked(true);

  apply_ = buttons_->addButton(tr("Apply"), QDialogButtonBox::AcceptRole);
  connect(buttons_, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons_, &QDialogButtonBox::rejected, this, &QDialog::reject);

  auto* layout = new QVBoxLayout(this);
  layout->addLayout(makeFileRows());
  layout->addWidget(summary_);
  layout->addWidget(trees, 1);
  layout->addWidget(rootMotion_);
  layout->addWidget(buttons_);
  resize(980, 640);
  rematch();
}

// The BVH and the optional map, each with its chooser.
QGridLayout* ApplyMotionDialog::makeFileRows() {
  motionPath_->setReadOnly(true);
  motionPath_->setPlaceholderText(tr("choose a BVH file"));
  mapPath_->setReadOnly(true);
  mapPath_->setPlaceholderText(tr("none: joints match by name, then by humanoid role"));
  auto* browseMotion = new QPushButton(tr("Browse..."));
  auto* browseMap = new QPushButton(tr("Browse..."));
  auto* clearMap = new QPushButton(tr("Clear"));
  connect(browseMotion, &QPushButton::clicked, this, &ApplyMotionDialog::browseMotion);
  connect(browseMap, &QPushButton::clicked, this, &ApplyMotionDialog::browseNameMap);
  connect(clearMap, &QPushButton::clicked, this, [this] { setNameMapFile(QString()); });

  auto* rows = new QGridLayout;
  rows->addWidget(new QLabel(tr("Motion (BVH):")), 0, 0);
  rows->addWidget(motionPath_, 0, 1);
  rows->addWidget(browseMotion, 0, 2);
  rows->addWidget(new QLabel(tr("Bone-name map:")), 1, 0);
  rows->addWidget(mapPath_, 1, 1);
  rows->addWidget(browseMap, 1, 2);
  rows->addWidget(clearMap, 1, 3);
  return rows;
}

QString ApplyMotionDialog::motionFile() const { return motionPath_->text(); }
QString ApplyMotionDialog::nameMapFile() const { return mapPath_->text(); }
bool ApplyMotionDialog::inPlace() const { return !rootMotion_->isChecked(); }

void ApplyMotionDialog::setMotionFile(const QString& bvhPath) {
  motionPath_->setText(bvhPath);
  motion_.reset();
  try {
    motion_ = loadBvhCharacter(bvhPath.toStdString()).skeleton;
  } catch (const std::exception& e) {
    showProblem(QString::fromUtf8(e.what()));
    return;
  }
  rematch();
}

void ApplyMotionDialog::setNameMapFile(const QString& mapPath) {
  mapPath_->setText(mapPath);
  if (motion_) rematch();
}

void ApplyMotionDialog::browseMotion() {
  const QString path = QFileDialog::getOpenFileName(this, tr("Motion"), lastDirectory(), motionFilter());
  if (path.isEmpty()) return;
  QSettings().setValue("lastDirectory", QFileInfo(path).absolutePath());
  setMotionFile(path);
}

void ApplyMotionDialog::browseNameMap() {
  const QString start = motionFile().isEmpty() ? lastDirectory() : QFileInfo(motionFile()).absolutePath();
  const QString path = QFileDialog::getOpenFileName(this, tr("Bone-name map"), start, nameMapFilter());
  if (!path.isEmpty()) setNameMapFile(path);
}

// Pairs the joints again with the current files and shows the result.
void ApplyMotionDialog::rematch() {
  report_.reset();
  if (motion_) {
    try {
      report_ = matchBones(*motion_, character_, nameMapFile().toStdString());
    } catch (const std::exception& e) {
      showProblem(QString::fromUtf8(e.what()));
      return;
    }
  }
  fillMotionTree();
  fillCharacterTree();
  const bool usable = report_ && report_->matchedCount() > 0;
  applyButton()->setEnabled(usable);
  summary_->setStyleSheet(QString());
  if (!motion_)
    summary_->setText(tr("Choose a BVH motion to see how its joints match %1's bones.").arg(characterName_));
  else if (!usable)
    showProblem(tr("No joint of this motion matches a bone of %1: choose a bone-name map.").arg(characterName_));
  else
    summary_->setText(QString::fromStdString(report_->summary(12)).replace("; ", "\n"));  // one list a line
}

// A problem with the chosen files: said in the dialog, and nothing to apply.
void ApplyMotionDialog::showProblem(const QString& message) {
  summary_->setText(message);
  summary_->setStyleSheet("color: #ff7060;");
  applyButton()->setEnabled(false);
  if (!report_) {
    motionTree_->clear();
    fillCharacterTree();
  }
}

void ApplyMotionDialog::fillMotionTree() {
  motionTree_->clear();
  if (!report_) return;
  std::vector<QTreeWidgetItem*> items;
  for (const JointMatch& joint : report_->joints) {
    auto* item = joint.parent >= 0 ? new QTreeWidgetItem(items[joint.parent]) : new QTreeWidgetItem(motionTree_);
    item->setText(0, QString::fromStdString(joint.joint));
    if (joint.bone >= 0) {
      item->setText(1, QString::fromStdString(character_.bone(joint.bone).name));
      const QString how = matchSourceName(joint.source);
      item->setText(2, joint.role.empty() ? how : how + " (" + QString::fromStdString(joint.role) + ")");
    } else {
      highlightUnmatched(item);
    }
    items.push_back(item);
  }
  motionTree_->expandAll();
}

void ApplyMotionDialog::fillCharacterTree() {
  characterTree_->clear();
  std::vector<QString> driver(character_.boneCount());
  if (report_)
    for (const JointMatch& joint : report_->joints)
      if (joint.bone >= 0) driver[joint.bone] = QString::fromStdString(joint.joint);
  std::vector<QTreeWidgetItem*> items;
  for (int b = 0; b < character_.boneCount(); ++b) {
    const Bone& bone = character_.bone(b);
    auto* item = bone.parent >= 0 ? new QTreeWidgetItem(items[bone.parent]) : new QTreeWidgetItem(characterTree_);
    item->setText(0, QString::fromStdString(bone.name));
    item->setText(1, driver[b]);
    if (report_ && driver[b].isEmpty()) highlightUnmatched(item);
    items.push_back(item);
  }
  characterTree_->expandAll();
}

}  // namespace mq::ui
