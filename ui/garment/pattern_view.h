#pragma once
// The selected garment's sewing pattern, drawn flat at true size beside the
// 3D viewport: every panel on a centimetre grid, its sewing line, its seams
// as pairs of edges in one colour with arrows giving the sewing direction, a
// notch and the seam's number on both edges, the grain line and the panel's
// name; seams whose edges differ in length by more than 5 mm are dashed and
// listed. The wheel zooms about the pointer, a drag pans, a double click fits.

#include <optional>

#include <QPointF>
#include <QWidget>

#include "core/garment/garment.h"

namespace mq::ui {

class PatternView : public QWidget {
  Q_OBJECT

 public:
  explicit PatternView(QWidget* parent = nullptr);

  // Shows `garment` (a copy is kept); none: an empty sheet with a hint.
  void setGarment(const std::optional<Garment>& garment);
  const std::optional<Garment>& garment() const { return garment_; }
  // Pixels per metre of pattern (the view fits the pattern when it is shown).
  double scale() const { return scale_; }
  // The seams drawn as differing in length (1-based numbers, as labelled).
  const std::vector<int>& unevenSeams() const { return uneven_; }
  // Where panel `panel`'s pattern point `p` (metres) is drawn, in widget pixels.
  QPointF toWidget(size_t panel, glm::vec2 p) const;
  void fit();
  // The finest grid drawn, in centimetres: 1, or 10 when 1 cm is under 4 pixels.
  int gridStep() const;

  static constexpr float kSeamLengthTolerance = 0.005f;  // metres

 protected:
  void paintEvent(QPaintEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseDoubleClickEvent(QMouseEvent* event) override;

 private:
  void layOut();  // each panel's offset on the sheet, left to right, tops level

  std::optional<Garment> garment_;
  std::vector<glm::vec2> offsets_;  // per panel: added to its pattern points (metres, on the sheet)
  glm::vec2 sheetMin_{0.0f}, sheetMax_{0.0f};
  std::vector<int> uneven_;
  double scale_ = 500.0;  // pixels per metre
  QPointF origin_;        // widget position of sheet point (0, 0)
  QPointF dragFrom_;
  bool userView_ = false;  // zoomed or panned: kept across edits and resizes
};

}  // namespace mq::ui
