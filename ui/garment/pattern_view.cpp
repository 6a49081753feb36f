#include "ui/garment/pattern_view.h"

#include <algorithm>
#include <cmath>

#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QWheelEvent>

#include "core/garment/pattern_outline.h"
#include "core/util/error.h"

namespace mq::ui {
namespace {

constexpr float kGap = 0.05f;     // metres between panels on the sheet
constexpr float kMargin = 0.04f;  // metres around the sheet when fitting
constexpr float kNotchDepth = 0.008f;

void drawArrowHead(QPainter& painter, QPointF tip, QPointF from, double size) {
  const QPointF d = tip - from;
  const double length = std::hypot(d.x(), d.y());
  if (length <= 0.0) return;
  const QPointF u = d / length, n(-u.y(), u.x());
  painter.drawPolygon(QPolygonF{tip, tip - u * size + n * size * 0.5, tip - u * size - n * size * 0.5});
}

}  // namespace

PatternView::PatternView(QWidget* parent) : QWidget(parent) {
  setMinimumSize(200, 150);
  setMouseTracking(false);
  setToolTip(
      tr("The garment's sewing pattern at true size (1 cm grid): wheel to zoom, drag to pan, "
         "double-click to fit"));
}

void PatternView::setGarment(const std::optional<Garment>& garment) {
  const bool sameGarment = garment_ && garment && garment_->name == garment->name;
  garment_ = garment;
  layOut();
  if (!sameGarment || !userView_) fit();  // an edit keeps where the user looks
  update();
}

void PatternView::layOut() {
  offsets_.clear();
  uneven_.clear();
  sheetMin_ = sheetMax_ = glm::vec2(0.0f);
  if (!garment_) return;
  float left = 0.0f;
  for (const Panel& panel : garment_->panels) {
    const std::vector<glm::vec2> outline = panel.outline(kPatternOutlineSegment);
    glm::vec2 low = outline[0], high = outline[0];
    for (glm::vec2 p : outline) low = glm::min(low, p), high = glm::max(high, p);
    offsets_.push_back({left - low.x, -high.y});  // tops at sheet y = 0
    left += high.x - low.x + kGap;
    sheetMin_.y = std::min(sheetMin_.y, low.y - high.y);
  }
  sheetMax_.x = std::max(0.0f, left - kGap);
  try {
    const std::vector<SeamLengths> lengths = seamLengths(*garment_);
    for (size_t s = 0; s < lengths.size(); ++s)
      if (std::abs(lengths[s].a - lengths[s].b) > kSeamLengthTolerance) uneven_.push_back(int(s) + 1);
  } catch (const Error&) {
  }
}

void PatternView::fit() {
  if (width() <= 0 || height() <= 0) return;
  const glm::vec2 size = sheetMax_ - sheetMin_ + glm::vec2(2.0f * kMargin);
  scale_ = std::clamp(std::min(width() / double(size.x), (height() - 24.0) / double(size.y)), 20.0, 20000.0);
  const glm::vec2 centre = 0.5f * (sheetMin_ + sheetMax_);
  origin_ = QPointF(width() / 2.0 - centre.x * scale_, 12.0 + height() / 2.0 + centre.y * scale_);
  userView_ = false;
}

int PatternView::gridStep() const { return scale_ / 100.0 >= 4.0 ? 1 : 10; }

QPointF PatternView::toWidget(size_t panel, glm::vec2 p) const {
  const glm::vec2 sheet = p + (panel < offsets_.size() ? offsets_[panel] : glm::vec2(0.0f));
  return origin_ + QPointF(sheet.x * scale_, -sheet.y * scale_);  // pattern v up, widget y down
}

void PatternView::resizeEvent(QResizeEvent*) {
  if (!userView_) fit();
}

void PatternView::wheelEvent(QWheelEvent* event) {
  const double factor = std::pow(1.0015, event->angleDelta().y());
  const double next = std::clamp(scale_ * factor, 20.0, 20000.0);
  const QPointF at = event->position();
  origin_ = at + (origin_ - at) * (next / scale_);
  scale_ = next;
  userView_ = true;
  update();
}

void PatternView::mousePressEvent(QMouseEvent* event) { dragFrom_ = event->position(); }

void PatternView::mouseMoveEvent(QMouseEvent* event) {
  origin_ += event->position() - dragFrom_;
  dragFrom_ = event->position();
  userView_ = true;
  update();
}

void PatternView::mouseDoubleClickEvent(QMouseEvent*) {
  fit();
  update();
}

void PatternView::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  painter.setRenderHint(QPainter::Antialiasing);
  painter.fillRect(rect(), QColor("#f4f1ea"));
  // The grid: 1 cm, every 10 cm darker (only what is wide enough to see).
  const double pixelsPerCm = scale_ / 100.0;
  for (int step : {1, 10}) {
    if (step < gridStep()) continue;
    painter.setPen(QPen(step == 1 ? QColor("#e6e1d6") : QColor("#cfc7b6"), 1.0));
    const double spacing = pixelsPerCm * step;
    for (double x = std::fmod(origin_.x(), spacing); x < width(); x += spacing)
      painter.drawLine(QPointF(x, 0), QPointF(x, height()));
    for (double y = std::fmod(origin_.y(), spacing); y < height(); y += spacing)
      painter.drawLine(QPointF(0, y), QPointF(width(), y));
  }
  if (!garment_) {
    painter.setPen(QColor("#6b6456"));
    painter.drawText(rect(), Qt::AlignCenter, tr("Select a garment to see its sewing pattern"));
    return;
  }
  const Garment& g = *garment_;
  for (size_t p = 0; p < g.panels.size(); ++p) {
    const Panel& panel = g.panels[p];
    QPainterPath outline;
    const std::vector<glm::vec2> points = panel.outline(std::max(0.001, 2.0 / scale_));
    outline.moveTo(toWidget(p, points[0]));
    for (size_t i = 1; i < points.size(); ++i) outline.lineTo(toWidget(p, points[i]));
    outline.closeSubpath();
    painter.setPen(QPen(Qt::black, 1.2));
    painter.setBrush(QColor("#fffdf8"));
    painter.drawPath(outline);
    // Grain line with arrows at both ends, the name beside it.
    const PatternSegment grain = grainLine(panel);
    const QPointF from = toWidget(p, grain.from), to = toWidget(p, grain.to);
    painter.setPen(QPen(QColor("#555555"), 1.0));
    painter.setBrush(QColor("#555555"));
    painter.drawLine(from, to);
    drawArrowHead(painter, to, from, 7.0);
    drawArrowHead(painter, from, to, 7.0);
    painter.setPen(Qt::black);
    painter.drawText(from + 0.75 * (to - from) + QPointF(6.0, 0.0), QString::fromStdString(panel.name));
  }
  // Seams: both edges in the seam's colour, an arrow along each in the
  // direction they are sewn together, a notch and the number.
  for (size_t s = 0; s < g.seams.size(); ++s) {
    const Seam& seam = g.seams[s];
    const QColor colour(seamColour(s));
    const bool uneven = std::find(uneven_.begin(), uneven_.end(), int(s) + 1) != uneven_.end();
    for (bool sideA : {true, false}) {
      const int p = g.findPanel(sideA ? seam.panelA : seam.panelB);
      if (p < 0) continue;
      const Panel& panel = g.panels[size_t(p)];
      const int e = panel.findEdge(sideA ? seam.edgeA : seam.edgeB);
      if (e < 0) continue;
      const std::vector<glm::vec2> samples = panel.sampleEdge(e, 32);
      QPainterPath path;
      path.moveTo(toWidget(size_t(p), samples[0]));
      for (size_t i = 1; i < samples.size(); ++i) path.lineTo(toWidget(size_t(p), samples[i]));
      painter.setBrush(Qt::NoBrush);
      painter.setPen(QPen(colour, 3.0, uneven ? Qt::DashLine : Qt::SolidLine, Qt::RoundCap));
      painter.drawPath(path);
      // B runs against A when reversed: its arrow points from its end to its start.
      const bool backwards = !sideA && seam.reversed;
      const size_t head = backwards ? 8 : 24, tail = backwards ? 12 : 20;
      painter.setBrush(colour);
      painter.setPen(QPen(colour, 1.0));
      drawArrowHead(painter, toWidget(size_t(p), samples[head]), toWidget(size_t(p), samples[tail]), 9.0);
      const PatternSegment notch = edgeNotch(panel, e, kNotchDepth);
      painter.setPen(QPen(Qt::black, 1.0));
      painter.drawLine(toWidget(size_t(p), notch.from), toWidget(size_t(p), notch.to));
      painter.setPen(colour);
      const QPointF label = toWidget(size_t(p), notch.from + (notch.to - notch.from) * 2.8f);
      painter.drawText(QRectF(label - QPointF(12, 8), QSizeF(24, 16)), Qt::AlignCenter, QString::number(s + 1));
    }
  }
  // What the drawing means, and which seams ease or pucker.
  painter.setPen(QColor("#3b372f"));
  QString caption = tr("%1: %2 panels, %3 seams; grid %4 cm")
                        .arg(QString::fromStdString(g.name))
                        .arg(g.panels.size())
                        .arg(g.seams.size())
                        .arg(gridStep());
  if (!uneven_.empty()) {
    QStringList numbers;
    for (int n : uneven_) numbers << QString::number(n);
    caption += tr("; edges differ by over 5 mm (dashed): seam %1").arg(numbers.join(", "));
  }
  painter.drawText(QRectF(6, 2, width() - 12, 20), Qt::AlignLeft | Qt::AlignVCenter, caption);
}

}  // namespace mq::ui
