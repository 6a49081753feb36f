#include "ui/export/export_animated_dialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QVBoxLayout>

namespace mq::ui {

ExportAnimatedDialog::ExportAnimatedDialog(const ExportAnimatedSources& sources, const QString& path, QWidget* parent)
    : QDialog(parent),
      sources_(sources),
      path_(new QLineEdit(path)),
      clips_(new QRadioButton(tr("Every clip (%1), sampled at").arg(sources.clipCount))),
      fps_(new QDoubleSpinBox),
      take_(new QRadioButton(tr("The baked take"))),
      garments_(new QCheckBox),
      hair_(new QCheckBox),
      pointCache_(new QComboBox),
      note_(new QLabel) {
  setWindowTitle(tr("Export Animated glTF"));
  auto* browse = new QPushButton(tr("Browse..."));
  connect(browse, &QPushButton::clicked, this, &ExportAnimatedDialog::browse);
  auto* fileRow = new QHBoxLayout;
  fileRow->addWidget(path_, 1);
  fileRow->addWidget(browse);

  fps_->setRange(1.0, 240.0);
  fps_->setValue(30.0);
  fps_->setSuffix(tr(" fps"));
  auto* clipsRow = new QHBoxLayout;
  clipsRow->addWidget(clips_);
  clipsRow->addWidget(fps_);
  clipsRow->addStretch(1);

  const bool garmentBake = !sources.garmentBake.isEmpty(), hairBake = !sources.hairBake.isEmpty();
  garments_->setText(garmentBake ? tr("Garments: %1").arg(sources.garmentBake) : tr("Garments (no bake)"));
  hair_->setText(hairBake ? tr("Hair guides: %1").arg(sources.hairBake) : tr("Hair (no bake)"));
  garments_->setChecked(garmentBake);
  hair_->setChecked(hairBake);
  pointCache_->addItem(tr("None"), QString());
  pointCache_->addItem(tr("PC2 (Blender, 3ds Max, Maya)"), QString("pc2"));
  pointCache_->addItem(tr("MDD (LightWave, Blender)"), QString("mdd"));
  auto* takeForm = new QFormLayout;
  takeForm->addRow(garments_);
  takeForm->addRow(hair_);
  takeForm->addRow(tr("Point caches beside it:"), pointCache_);
  takeForm->setContentsMargins(24, 0, 0, 0);

  auto* animation = new QGroupBox(tr("Animation"));
  auto* animationLayout = new QVBoxLayout(animation);
  animationLayout->addLayout(clipsRow);
  animationLayout->addWidget(take_);
  animationLayout->addLayout(takeForm);
  (garmentBake || hairBake ? take_ : clips_)->setChecked(true);
  take_->setEnabled(garmentBake || hairBake);
  note_->setWordWrap(true);

  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Cancel);
  export_ = buttons->addButton(tr("Export"), QDialogButtonBox::AcceptRole);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  for (QAbstractButton* b : {static_cast<QAbstractButton*>(clips_), static_cast<QAbstractButton*>(take_),
                             static_cast<QAbstractButton*>(garments_), static_cast<QAbstractButton*>(hair_)})
    connect(b, &QAbstractButton::toggled, this, &ExportAnimatedDialog::updateEnabled);
  connect(path_, &QLineEdit::textChanged, this, &ExportAnimatedDialog::updateEnabled);

  auto* layout = new QVBoxLayout(this);
  layout->addLayout(fileRow);
  layout->addWidget(animation);
  layout->addWidget(note_);
  layout->addWidget(buttons);
  resize(560, sizeHint().height());
  updateEnabled();
}

ExportAnimatedChoice ExportAnimatedDialog::choice() const {
  ExportAnimatedChoice c;
  c.path = path_->text().trimmed();
  c.take = take_->isChecked();
  c.garments = c.take && garments_->isChecked() && garments_->isEnabled();
  c.hair = c.take && hair_->isChecked() && hair_->isEnabled();
  c.clipFps = float(fps_->value());
  c.pointCache = c.take ? pointCache_->currentData().toString() : QString();
  return c;
}

void ExportAnimatedDialog::browse() {
  QString filter;
  QString path = QFileDialog::getSaveFileName(this, tr("Export Animated glTF"), path_->text(),
                                              tr("glTF binary (*.glb);;glTF with embedded data (*.gltf)"), &filter);
  if (path.isEmpty()) return;
  if (QFileInfo(path).suffix().isEmpty()) path += filter.contains("gltf)") ? ".gltf" : ".glb";
  path_->setText(path);
}

// The take's options follow the choice of the take; Export needs a .glb or
// .gltf path and, for a take, at least one surface.
void ExportAnimatedDialog::updateEnabled() {
  const bool take = take_->isChecked();
  fps_->setEnabled(!take);
  garments_->setEnabled(take && !sources_.garmentBake.isEmpty());
  hair_->setEnabled(take && !sources_.hairBake.isEmpty());
  pointCache_->setEnabled(take);
  const QString suffix = QFileInfo(path_->text().trimmed()).suffix().toLower();
  QString problem;
  if (suffix != "glb" && suffix != "gltf")
    problem = tr("Choose a .glb or .gltf file.");
  else if (take && !garments_->isChecked() && !hair_->isChecked())
    problem = tr("Choose the garments, the hair or both for the take.");
  note_->setText(problem.isEmpty() ? (take ? tr("The character plays the baked frames; each baked surface is a mesh "
                                                "whose frames are morph targets.")
                                           : tr("The character with its skeleton, skin, morph targets, materials "
                                                "and every clip."))
                                   : problem);
  export_->setEnabled(problem.isEmpty());
}

}  // namespace mq::ui
