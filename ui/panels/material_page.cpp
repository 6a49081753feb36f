#include "ui/panels/material_page.h"

#include <functional>

#include <QCheckBox>
#include <QColorDialog>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QImage>
#include <QLabel>
#include <QPixmap>
#include <QPushButton>
#include <QUndoStack>
#include <QVBoxLayout>

#include "core/material/material_override.h"
#include "ui/document/editor_document.h"
#include "ui/document/material_commands.h"

namespace mq::ui {
namespace {

// Factors are linear; a colour picker works in sRGB, as the user sees it.
QColor toQColor(const glm::vec4& linear) {
  return QColor::fromRgbF(linearToSrgb(linear.x), linearToSrgb(linear.y), linearToSrgb(linear.z), linear.w);
}

glm::vec4 fromQColor(const QColor& c) {
  return {srgbToLinear(float(c.redF())), srgbToLinear(float(c.greenF())), srgbToLinear(float(c.blueF())),
          float(c.alphaF())};
}

// The base colour texture as a small picture (Qt decodes PNG and JPEG);
// empty when there is none or it does not decode.
QPixmap thumbnailOf(const Material& m, const Character& character) {
  const TextureRef& ref = m.baseColorTexture;
  if (!ref.present() || ref.image >= static_cast<int>(character.images.size())) return {};
  const ImageSource& source = character.images[ref.image];
  QImage image;
  if (!source.path.empty())
    image.load(QString::fromStdString(source.path));
  else
    image.loadFromData(source.encoded.data(), static_cast<int>(source.encoded.size()));
  if (image.isNull()) return {};
  return QPixmap::fromImage(image.scaled(96, 96, Qt::KeepAspectRatio, Qt::SmoothTransformation));
}

QString textureList(const Material& m, const Character& character) {
  QStringList lines;
  for (const TextureSlot& slot : m.textureSlots())
    if (slot.ref->present() && slot.ref->image < static_cast<int>(character.images.size()))
      lines << QObject::tr("%1: %2").arg(slot.label, QString::fromStdString(character.images[slot.ref->image].name));
  return lines.isEmpty() ? QObject::tr("none") : lines.join("\n");
}

}  // namespace

MaterialPage::MaterialPage(EditorDocument* document, QWidget* parent) : QWidget(parent), document_(document) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  auto* box = new QGroupBox(tr("Material"));
  form_ = new QFormLayout(box);
  name_ = new QLabel;
  name_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  form_->addRow(tr("Name"), name_);
  textures_ = new QLabel;
  textures_->setWordWrap(true);
  form_->addRow(tr("Textures"), textures_);
  thumbnail_ = new QLabel;
  form_->addRow(QString(), thumbnail_);

  baseColour_ = new QPushButton;
  baseColour_->setToolTip(tr("Base colour factor (multiplies the base colour texture) and opacity"));
  connect(baseColour_, &QPushButton::clicked, this, [this] { pickColour(tr("Base colour"), true, true); });
  form_->addRow(tr("Base colour"), baseColour_);
  metallic_ =
      addFactor(tr("Metallic"), 1.0, 0.05, tr("0: dielectric (skin, cloth); 1: metal"), &Material::metallicFactor);
  roughness_ = addFactor(tr("Roughness"), 1.0, 0.05, tr("0: mirror-like; 1: fully diffuse highlights"),
                         &Material::roughnessFactor);
  normalScale_ =
      addFactor(tr("Normal strength"), 10.0, 0.1, tr("Scales the normal map's bumps"), &Material::normalScale);
  occlusion_ = addFactor(tr("Occlusion"), 1.0, 0.05, tr("How much the occlusion map darkens ambient light"),
                         &Material::occlusionStrength);
  emissive_ = new QPushButton;
  connect(emissive_, &QPushButton::clicked, this, [this] { pickColour(tr("Emission"), false, false); });
  form_->addRow(tr("Emission"), emissive_);
  emissiveStrength_ = addFactor(tr("Emission strength"), 1000.0, 0.5, tr("Multiplies the emission colour"),
                                &Material::emissiveStrength);

  alphaMode_ = new QComboBox;
  alphaMode_->addItem(tr("Opaque"), int(AlphaMode::Opaque));
  alphaMode_->addItem(tr("Mask (cut out)"), int(AlphaMode::Mask));
  alphaMode_->addItem(tr("Blend (translucent)"), int(AlphaMode::Blend));
  connect(alphaMode_, &QComboBox::activated, this, [this](int i) {
    const auto mode = AlphaMode(alphaMode_->itemData(i).toInt());
    edit(tr("Alpha mode"), [mode](Material& m) { m.alphaMode = mode; });
  });
  form_->addRow(tr("Alpha"), alphaMode_);
  alphaCutoff_ = addFactor(tr("Alpha cutoff"), 1.0, 0.05, tr("Mask mode: texels below this opacity are cut away"),
                           &Material::alphaCutoff);
  doubleSided_ = new QCheckBox(tr("Double-sided"));
  connect(doubleSided_, &QCheckBox::toggled, this,
          [this](bool on) { edit(tr("Double-sided"), [on](Material& m) { m.doubleSided = on; }); });
  form_->addRow(QString(), doubleSided_);
  skin_ = new QCheckBox(tr("Skin"));
  skin_->setToolTip(tr("Shade this material as skin (subsurface scattering); its base colour becomes the albedo"));
  connect(skin_, &QCheckBox::toggled, this, [this](bool on) { edit(tr("Skin"), [on](Material& m) { m.skin = on; }); });
  form_->addRow(QString(), skin_);

  changed_ = new QLabel;
  changed_->setEnabled(false);
  reset_ = new QPushButton(tr("Reset to file"));
  reset_->setToolTip(tr("Drop the changes made here; the file's own values come back"));
  connect(reset_, &QPushButton::clicked, this, [this] {
    if (const Material* original = document_->fileMaterial(index_))
      document_->undoStack()->push(new SetMaterialCommand(document_, index_, *original, tr("Reset")));
  });
  form_->addRow(changed_, reset_);
  layout->addWidget(box);

  connect(document_, &EditorDocument::materialChanged, this, [this](int index) {
    if (index == index_) showMaterial(index);
  });
}

QDoubleSpinBox* MaterialPage::addFactor(const QString& label, double max, double step, const QString& tip,
                                        float Material::*field) {
  auto* box = new QDoubleSpinBox;
  box->setRange(0.0, max);
  box->setSingleStep(step);
  box->setDecimals(3);
  box->setKeyboardTracking(false);  // one undo step per typed value
  box->setToolTip(tip);
  connect(box, &QDoubleSpinBox::valueChanged, this, [this, label, field](double value) {
    edit(label, [field, value](Material& m) { m.*field = float(value); });
  });
  form_->addRow(label, box);
  return box;
}

void MaterialPage::edit(const QString& what, const std::function<void(Material&)>& change) {
  if (syncing_ || index_ < 0) return;
  Material edited = document_->character().materials.at(index_);
  change(edited);
  if (MaterialOverride::between(document_->character().materials[index_], edited).empty()) return;
  document_->undoStack()->push(new SetMaterialCommand(document_, index_, edited, what));
}

void MaterialPage::pickColour(const QString& what, bool withAlpha, bool base) {
  if (index_ < 0) return;
  const Material& m = document_->character().materials[index_];
  const QColor current = base ? toQColor(m.baseColorFactor) : toQColor(glm::vec4(m.emissiveFactor, 1.0f));
  const QColor picked = QColorDialog::getColor(
      current, this, what, withAlpha ? QColorDialog::ShowAlphaChannel : QColorDialog::ColorDialogOptions());
  if (!picked.isValid()) return;
  const glm::vec4 linear = fromQColor(picked);
  edit(what, [&](Material& e) {
    if (base)
      e.baseColorFactor = linear;
    else
      e.emissiveFactor = glm::vec3(linear);
  });
}

void MaterialPage::showColour(QPushButton* button, const QColor& colour) {
  button->setText(colour.name(QColor::HexRgb) +
                  (colour.alpha() < 255 ? QString(" (%1%)").arg(colour.alpha() * 100 / 255) : ""));
  button->setStyleSheet(QString("QPushButton { background: %1; color: %2; }")
                            .arg(colour.name(QColor::HexRgb), colour.lightnessF() > 0.55 ? "black" : "white"));
}

void MaterialPage::showMaterial(int index) {
  const Character& c = document_->character();
  index_ = index >= 0 && index < static_cast<int>(c.materials.size()) ? index : -1;
  if (index_ < 0) return;
  const Material& m = c.materials[index_];
  syncing_ = true;
  name_->setText(QString::fromStdString(m.name));
  textures_->setText(textureList(m, c));
  const QPixmap thumbnail = thumbnailOf(m, c);
  thumbnail_->setPixmap(thumbnail);
  thumbnail_->setVisible(!thumbnail.isNull());
  showColour(baseColour_, toQColor(m.baseColorFactor));
  metallic_->setValue(m.metallicFactor);
  roughness_->setValue(m.roughnessFactor);
  normalScale_->setValue(m.normalScale);
  normalScale_->setEnabled(m.normalTexture.present());
  occlusion_->setValue(m.occlusionStrength);
  occlusion_->setEnabled(m.occlusionTexture.present());
  showColour(emissive_, toQColor(glm::vec4(m.emissiveFactor, 1.0f)));
  emissiveStrength_->setValue(m.emissiveStrength);
  alphaMode_->setCurrentIndex(alphaMode_->findData(int(m.alphaMode)));
  alphaCutoff_->setValue(m.alphaCutoff);
  alphaCutoff_->setEnabled(m.alphaMode == AlphaMode::Mask);
  doubleSided_->setChecked(m.doubleSided);
  skin_->setChecked(m.skin);
  const Material* original = document_->fileMaterial(index_);
  const bool changed = original && !MaterialOverride::between(*original, m).empty();
  changed_->setText(changed ? tr("changed from the file") : tr("as in the file"));
  reset_->setEnabled(changed);
  syncing_ = false;
}

}  // namespace mq::ui
