#pragma once
// The Material page of the properties panel: a file material's factors and
// flags (base colour, metallic, roughness, normal and occlusion strengths,
// emission, alpha mode, double-sided, skin) and the textures it samples.
// Every change is one undo step; the scene document saves it as an override
// of the file's material.

#include <functional>

#include <QWidget>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QPushButton;

namespace mq {
struct Material;
}

namespace mq::ui {

class EditorDocument;

class MaterialPage : public QWidget {
  Q_OBJECT

 public:
  explicit MaterialPage(EditorDocument* document, QWidget* parent = nullptr);
  // Shows material `index` of the document's character.
  void showMaterial(int index);

  QDoubleSpinBox* roughnessBox() const { return roughness_; }
  QDoubleSpinBox* metallicBox() const { return metallic_; }
  QCheckBox* skinBox() const { return skin_; }
  QComboBox* alphaModeBox() const { return alphaMode_; }
  QPushButton* resetButton() const { return reset_; }
  QLabel* thumbnailLabel() const { return thumbnail_; }

 private:
  QDoubleSpinBox* addFactor(const QString& label, double max, double step, const QString& tip, float Material::*field);
  void edit(const QString& what, const std::function<void(Material&)>& change);
  void pickColour(const QString& what, bool withAlpha, bool base);
  void showColour(QPushButton* button, const QColor& colour);

  EditorDocument* document_;
  int index_ = -1;
  bool syncing_ = false;
  QFormLayout* form_ = nullptr;
  QLabel* name_ = nullptr;
  QLabel* textures_ = nullptr;
  QLabel* thumbnail_ = nullptr;  // the base colour texture, small
  QLabel* changed_ = nullptr;
  QPushButton* baseColour_ = nullptr;
  QDoubleSpinBox* metallic_ = nullptr;
  QDoubleSpinBox* roughness_ = nullptr;
  QDoubleSpinBox* normalScale_ = nullptr;
  QDoubleSpinBox* occlusion_ = nullptr;
  QPushButton* emissive_ = nullptr;
  QDoubleSpinBox* emissiveStrength_ = nullptr;
  QComboBox* alphaMode_ = nullptr;
  QDoubleSpinBox* alphaCutoff_ = nullptr;
  QCheckBox* doubleSided_ = nullptr;
  QCheckBox* skin_ = nullptr;
  QPushButton* reset_ = nullptr;
};

}  // namespace mq::ui
