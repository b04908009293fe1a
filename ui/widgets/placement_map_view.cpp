#include "ui/widgets/placement_map_view.h"

#include <QHelpEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QToolTip>
#include <cmath>

#include "core/placement/furniture_footprints.h"
#include "plot/painter_canvas.h"

namespace demoplan::ui {

PlacementMapView::PlacementMapView(Document* doc, QWidget* parent) : QWidget(parent), doc_(doc) {
  setMouseTracking(true);
  setMinimumSize(320, 240);
  auto* job = doc->placement();
  connect(job, &PlacementSearchJob::candidateDone, this, qOverload<>(&QWidget::update));
  connect(job, &PlacementSearchJob::cleared, this, [this] {
    chosen_ = -1;
    update();
  });
  connect(doc, &Document::sceneChanged, this, &PlacementMapView::refreshOutlines);
  connect(doc, &Document::projectLoaded, this, &PlacementMapView::refreshOutlines);
  refreshOutlines();
}

void PlacementMapView::refreshOutlines() {
  outlines_.clear();
  if (doc_->hasProject())
    for (const Footprint& f : furniture_footprints(doc_->scene())) {
      auto& polygon = outlines_.emplace_back();
      for (const Eigen::Vector2d& p : f.outline) polygon.emplace_back(p.x(), p.y());
    }
  update();
}

plot::HeatMap PlacementMapView::map() const {
  plot::HeatMap m;
  const PlacementSearchSettings s = doc_->placement()->settings();
  m.x_label = tr("x (m)");
  m.y_label = tr("y (m)");
  m.value_label = tr("cycle time (s)");
  m.grey_label = tr("no valid plan");
  m.marked_label = tr("chosen");
  m.references_label = tr("robot now");
  m.outlines = outlines_;
  m.outlines_label = tr("furniture");
  m.x0 = s.region.x.low, m.x1 = s.region.x.high, m.y0 = s.region.y.low, m.y1 = s.region.y.high;
  const int n = std::max(doc_->placement()->total(), 1);
  m.cell = 0.9 * std::sqrt((m.x1 - m.x0) * (m.y1 - m.y0) / n);
  for (const PlacementCandidate& c : doc_->placement()->candidates())
    m.samples.push_back({c.base.x, c.base.y, c.usable() ? *c.cycle_time_s() : std::nan(""), c.base.yaw});
  const auto& candidates = doc_->placement()->candidates();
  if (chosen_ >= 0 && chosen_ < static_cast<int>(candidates.size()))
    m.marked.push_back({candidates[static_cast<size_t>(chosen_)].base.x, candidates[static_cast<size_t>(chosen_)].base.y});
  if (doc_->hasProject()) {
    const Eigen::Vector3d base = doc_->scene().robot.base.translation();
    m.references.push_back({base.x(), base.y()});
  }
  return m;
}

int PlacementMapView::candidateAt(QPointF pixel) const { return plot::heat_map_sample_at(area(), map(), pixel); }

void PlacementMapView::choose(int candidate) {
  if (candidate == chosen_) return;
  chosen_ = candidate;
  update();
  emit chosenChanged(candidate);
}

QString PlacementMapView::describe(int index) const {
  const auto& candidates = doc_->placement()->candidates();
  if (index < 0 || index >= static_cast<int>(candidates.size())) return {};
  const PlacementCandidate& c = candidates[static_cast<size_t>(index)];
  QString where = tr("x %1 m, y %2 m, yaw %3°").arg(c.base.x, 0, 'f', 3).arg(c.base.y, 0, 'f', 3).arg(c.base.yaw * 180 / M_PI, 0, 'f', 0);
  if (!c.feasible) return where + QStringLiteral("\n") + QString::fromStdString(c.reason);
  QString text = where + tr("\nvalid plans: %1 of %2, planning %3 s (median)")
                             .arg(std::lround(c.success_rate() * static_cast<double>(c.runs.size())))
                             .arg(c.runs.size())
                             .arg(c.median_time_s(), 0, 'f', 2);
  if (c.cycle_time_s()) text += tr("\ncycle time %1 s").arg(*c.cycle_time_s(), 0, 'f', 2);
  else if (!c.runs.empty()) text += QStringLiteral("\n") + QString::fromStdString(c.runs.front().message);
  return text;
}

void PlacementMapView::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.fillRect(rect(), Qt::white);
  p.setRenderHint(QPainter::Antialiasing);
  plot::PainterCanvas canvas(p);
  draw_heat_map(canvas, area(), map());
}

void PlacementMapView::mousePressEvent(QMouseEvent* e) {
  if (e->button() == Qt::LeftButton) choose(candidateAt(e->position()));
}

void PlacementMapView::mouseDoubleClickEvent(QMouseEvent* e) {
  const int k = candidateAt(e->position());
  if (e->button() != Qt::LeftButton || k < 0) return;
  choose(k);
  emit standRequested(k);
}

bool PlacementMapView::event(QEvent* e) {
  if (e->type() == QEvent::ToolTip) {
    auto* help = static_cast<QHelpEvent*>(e);
    const QString text = describe(candidateAt(help->pos()));
    if (text.isEmpty()) QToolTip::hideText();
    else QToolTip::showText(help->globalPos(), text, this);
    return true;
  }
  return QWidget::event(e);
}

}  // namespace demoplan::ui
