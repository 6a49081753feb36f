#include "ui/icons.h"

#include <QPainter>
#include <QPainterPath>
#include <QPixmap>

namespace mq::ui {
namespace {

const QColor kInk(0xd8, 0xd8, 0xd8);
const QColor kAccent(0x5b, 0x9b, 0xf0);
const QColor kDisabledInk(0x6a, 0x6a, 0x6a);

QPainterPath triangle(QPointF a, QPointF b, QPointF c) {
  QPainterPath p;
  p.moveTo(a);
  p.lineTo(b);
  p.lineTo(c);
  p.closeSubpath();
  return p;
}

// Draws `icon` in a 24 x 24 box.
void draw(QPainter& p, Icon icon, const QColor& ink) {
  QPen pen(ink, 1.8, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin);
  p.setPen(pen);
  p.setBrush(Qt::NoBrush);
  switch (icon) {
    case Icon::New: {
      QPainterPath page;
      page.moveTo(6, 3);
      page.lineTo(14, 3);
      page.lineTo(19, 8);
      page.lineTo(19, 21);
      page.lineTo(6, 21);
      page.closeSubpath();
      p.drawPath(page);
      p.drawPolyline(QPolygonF({{14, 3}, {14, 8}, {19, 8}}));
      break;
    }
    case Icon::Open: {
      p.drawPolyline(QPolygonF({{3, 19}, {3, 5}, {9, 5}, {11, 7}, {19, 7}, {19, 10}}));
      p.drawPolygon(QPolygonF({{3, 19}, {7, 10}, {22, 10}, {18, 19}}));
      break;
    }
    case Icon::Save: {
      p.drawRoundedRect(QRectF(4, 4, 16, 16), 2, 2);
      p.drawRect(QRectF(8, 4, 8, 5));
      p.drawRect(QRectF(7, 13, 10, 7));
      break;
    }
    case Icon::Undo:
    case Icon::Redo: {
      p.save();
      if (icon == Icon::Redo) {
        p.translate(24, 0);
        p.scale(-1, 1);
      }
      QPainterPath arc;
      arc.moveTo(6, 10);
      arc.lineTo(15, 10);
      arc.cubicTo(22, 10, 22, 20, 15, 20);
      arc.lineTo(10, 20);
      p.drawPath(arc);
      p.drawPolyline(QPolygonF({{10, 6}, {6, 10}, {10, 14}}));
      p.restore();
      break;
    }
    case Icon::FrameAll: {
      for (QPointF c : {QPointF(4, 4), QPointF(20, 4), QPointF(20, 20), QPointF(4, 20)}) {
        const double sx = c.x() < 12 ? 1 : -1, sy = c.y() < 12 ? 1 : -1;
        p.drawPolyline(QPolygonF({{c.x(), c.y() + 5 * sy}, c, {c.x() + 5 * sx, c.y()}}));
      }
      p.setBrush(kAccent);
      p.setPen(Qt::NoPen);
      p.drawEllipse(QPointF(12, 12), 3.5, 3.5);
      break;
    }
    case Icon::Skeleton: {
      p.drawLine(QPointF(12, 6), QPointF(12, 14));  // spine
      p.drawLine(QPointF(6, 9), QPointF(18, 9));    // shoulders
      p.drawLine(QPointF(12, 14), QPointF(8, 21));  // legs
      p.drawLine(QPointF(12, 14), QPointF(16, 21));
      p.setBrush(kAccent);
      p.setPen(Qt::NoPen);
      for (QPointF j :
           {QPointF(12, 4), QPointF(6, 9), QPointF(18, 9), QPointF(12, 14), QPointF(8, 21), QPointF(16, 21)})
        p.drawEllipse(j, 2.2, 2.2);
      break;
    }
    case Icon::Play:
      p.setBrush(ink);
      p.drawPath(triangle({7, 4}, {20, 12}, {7, 20}));
      break;
    case Icon::Pause:
      p.setBrush(ink);
      p.drawRect(QRectF(6, 5, 4, 14));
      p.drawRect(QRectF(14, 5, 4, 14));
      break;
    case Icon::ToStart:
    case Icon::ToEnd: {
      p.save();
      if (icon == Icon::ToEnd) {
        p.translate(24, 0);
        p.scale(-1, 1);
      }
      p.setBrush(ink);
      p.drawRect(QRectF(5, 5, 2, 14));
      p.drawPath(triangle({19, 5}, {9, 12}, {19, 19}));
      p.restore();
      break;
    }
    case Icon::StepBack:
    case Icon::StepForward: {
      p.save();
      if (icon == Icon::StepForward) {
        p.translate(24, 0);
        p.scale(-1, 1);
      }
      p.setBrush(ink);
      p.drawPath(triangle({12, 6}, {4, 12}, {12, 18}));
      p.drawPath(triangle({20, 6}, {12, 12}, {20, 18}));
      p.restore();
      break;
    }
  }
}

QPixmap render(Icon icon, const QColor& ink, int size) {
  QPixmap pixmap(size, size);
  pixmap.fill(Qt::transparent);
  QPainter p(&pixmap);
  p.setRenderHint(QPainter::Antialiasing);
  p.scale(size / 24.0, size / 24.0);
  draw(p, icon, ink);
  return pixmap;
}

}  // namespace

QIcon makeIcon(Icon icon) {
  QIcon out;
  for (int size : {16, 24, 32, 48}) {
    out.addPixmap(render(icon, kInk, size), QIcon::Normal);
    out.addPixmap(render(icon, kDisabledInk, size), QIcon::Disabled);
  }
  return out;
}

}  // namespace mq::ui
