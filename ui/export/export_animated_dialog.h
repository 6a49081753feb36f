#pragma once
// File > Export Animated glTF: where to write and what. The character with
// every clip resampled at a chosen rate, or the baked take (the garment and
// hair bakes' frames, each surface a morph-target mesh) with the garments,
// the hair or both, and optionally the baked surfaces as point caches (PC2
// or MDD) beside the glTF, as `mannequin-cli export --with ... --point-cache`
// writes them.

#include <QDialog>
#include <QString>
#include <QStringList>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QRadioButton;

namespace mq::ui {

// What there is to export, from the editor's state.
struct ExportAnimatedSources {
  int clipCount = 0;
  QString garmentBake;  // e.g. "30 frames of walk, 2 surfaces"; empty: no garment bake
  QString hairBake;     // empty: no hair bake
};

// The user's choice.
struct ExportAnimatedChoice {
  QString path;           // .glb or .gltf
  bool take = false;      // the baked take, else every clip
  bool garments = false;  // with the take: the garment bake's surfaces
  bool hair = false;      // with the take: the hair guides
  float clipFps = 30.0f;  // every clip: the rate clips are sampled at
  QString pointCache;     // with the take: "pc2", "mdd" or empty (none)
};

class ExportAnimatedDialog : public QDialog {
  Q_OBJECT

 public:
  ExportAnimatedDialog(const ExportAnimatedSources& sources, const QString& path, QWidget* parent = nullptr);

  ExportAnimatedChoice choice() const;

  // For tests.
  QLineEdit* pathEdit() const { return path_; }
  QRadioButton* clipsButton() const { return clips_; }
  QRadioButton* takeButton() const { return take_; }
  QCheckBox* garmentsBox() const { return garments_; }
  QCheckBox* hairBox() const { return hair_; }
  QComboBox* pointCacheBox() const { return pointCache_; }
  QPushButton* exportButton() const { return export_; }

 private:
  void browse();
  void updateEnabled();

  ExportAnimatedSources sources_;
  QLineEdit* path_;
  QRadioButton* clips_;
  QDoubleSpinBox* fps_;
  QRadioButton* take_;
  QCheckBox* garments_;
  QCheckBox* hair_;
  QComboBox* pointCache_;
  QLabel* note_;
  QPushButton* export_ = nullptr;
};

}  // namespace mq::ui
