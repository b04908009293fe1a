#include "ui/widgets/step_bar.h"

#include <QHelpEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QToolTip>

#include "ui/widgets/style.h"

namespace demoplan::ui {

namespace {
const char* const kNames[] = {QT_TRANSLATE_NOOP("StepBar", "Video"), QT_TRANSLATE_NOOP("StepBar", "Events"),
                              QT_TRANSLATE_NOOP("StepBar", "Poses"), QT_TRANSLATE_NOOP("StepBar", "Plan"),
                              QT_TRANSLATE_NOOP("StepBar", "Export")};
constexpr int kStepWidth = 104;
constexpr int kGap = 14;
}  // namespace

void paintStatusIcon(QPainter& p, const QRectF& r, StepStatus status) {
  p.save();
  p.setRenderHint(QPainter::Antialiasing);
  const QPointF c = r.center();
  const double s = std::min(r.width(), r.height());
  switch (status) {
    case StepStatus::Ok: {
      p.setPen(Qt::NoPen);
      p.setBrush(kOkColor);
      p.drawEllipse(c, s / 2, s / 2);
      QPen pen(Qt::white, s * 0.14, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin);
      p.setPen(pen);
      p.setBrush(Qt::NoBrush);
      QPainterPath tick;
      tick.moveTo(c + QPointF(-s * 0.24, 0.0));
      tick.lineTo(c + QPointF(-s * 0.06, s * 0.18));
      tick.lineTo(c + QPointF(s * 0.25, -s * 0.17));
      p.drawPath(tick);
      break;
    }
    case StepStatus::Warning: {
      QPainterPath tri;
      tri.moveTo(c + QPointF(0, -s * 0.5));
      tri.lineTo(c + QPointF(s * 0.52, s * 0.42));
      tri.lineTo(c + QPointF(-s * 0.52, s * 0.42));
      tri.closeSubpath();
      p.setPen(Qt::NoPen);
      p.setBrush(kWarningColor);
      p.drawPath(tri);
      p.setPen(QPen(Qt::white, s * 0.13, Qt::SolidLine, Qt::RoundCap));
      p.drawLine(c + QPointF(0, -s * 0.18), c + QPointF(0, s * 0.1));
      p.drawPoint(c + QPointF(0, s * 0.27));
      break;
    }
    case StepStatus::Error: {
      p.setPen(Qt::NoPen);
      p.setBrush(kErrorColor);
      p.drawEllipse(c, s / 2, s / 2);
      p.setPen(QPen(Qt::white, s * 0.14, Qt::SolidLine, Qt::RoundCap));
      const double d = s * 0.18;
      p.drawLine(c + QPointF(-d, -d), c + QPointF(d, d));
      p.drawLine(c + QPointF(-d, d), c + QPointF(d, -d));
      break;
    }
    case StepStatus::Busy: {
      p.setPen(QPen(kBusyColor, s * 0.16));
      p.setBrush(Qt::NoBrush);
      p.drawArc(QRectF(c.x() - s * 0.4, c.y() - s * 0.4, s * 0.8, s * 0.8), 90 * 16, 270 * 16);
      break;
    }
    case StepStatus::None:
      p.setPen(QPen(QColor(0x9a, 0xa0, 0xa6), s * 0.12));
      p.setBrush(Qt::NoBrush);
      p.drawEllipse(c, s * 0.38, s * 0.38);
      break;
  }
  p.restore();
}

StepBar::StepBar(QWidget* parent) : QWidget(parent) {
  setMouseTracking(true);
  setCursor(Qt::PointingHandCursor);
  setAccessibleName(tr("Job steps"));
}

QSize StepBar::sizeHint() const { return {5 * kStepWidth + 4 * kGap + 8, 30}; }
QSize StepBar::minimumSizeHint() const { return sizeHint(); }

QRect StepBar::stepRect(Step step) const {
  const int i = int(step);
  const int h = height() - 4;
  return QRect(4 + i * (kStepWidth + kGap), 2, kStepWidth, h);
}

void StepBar::setState(Step step, const StepState& state) {
  states_[int(step)] = state;
  update();
}

void StepBar::setCurrent(Step step) {
  current_ = step;
  update();
}

void StepBar::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.setRenderHint(QPainter::Antialiasing);
  const QPalette pal = palette();
  for (int i = 0; i < 5; ++i) {
    const QRectF r = stepRect(Step(i)).adjusted(0.5, 0.5, -0.5, -0.5);
    const bool current = Step(i) == current_;
    if (i > 0) {  // connector
      p.setPen(QPen(pal.color(QPalette::Mid), 2));
      const double y = r.center().y();
      p.drawLine(QPointF(r.left() - kGap + 2, y), QPointF(r.left() - 2, y));
    }
    p.setPen(QPen(current ? kBusyColor : pal.color(QPalette::Mid), current ? 2 : 1));
    p.setBrush(current ? QColor(0xe7, 0xf0, 0xfd) : pal.color(QPalette::Button));
    p.drawRoundedRect(r, r.height() / 2, r.height() / 2);
    const double icon = r.height() - 10;
    paintStatusIcon(p, QRectF(r.left() + 6, r.top() + 5, icon, icon), states_[i].status);
    QFont f = font();
    f.setBold(current);
    p.setFont(f);
    p.setPen(current ? QColor(0x0b, 0x3d, 0x91) : pal.color(QPalette::ButtonText));
    p.drawText(r.adjusted(icon + 12, 0, -6, 0), Qt::AlignVCenter | Qt::AlignLeft,
               QStringLiteral("%1 %2").arg(i + 1).arg(tr(kNames[i])));
  }
}

void StepBar::mousePressEvent(QMouseEvent* e) {
  for (int i = 0; i < 5; ++i)
    if (stepRect(Step(i)).contains(e->position().toPoint())) {
      setCurrent(Step(i));
      emit stepClicked(Step(i));
      return;
    }
}

bool StepBar::event(QEvent* e) {
  if (e->type() == QEvent::ToolTip) {
    auto* he = static_cast<QHelpEvent*>(e);
    for (int i = 0; i < 5; ++i)
      if (stepRect(Step(i)).contains(he->pos())) {
        QToolTip::showText(he->globalPos(),
                           QStringLiteral("<b>%1 %2</b><br>%3").arg(i + 1).arg(tr(kNames[i]), states_[i].message.toHtmlEscaped()),
                           this, stepRect(Step(i)));
        return true;
      }
    QToolTip::hideText();
    return true;
  }
  return QWidget::event(e);
}

}  // namespace demoplan::ui
