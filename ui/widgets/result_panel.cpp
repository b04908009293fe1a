#include "ui/widgets/result_panel.h"

#include "core/validation/path_validator.h"

#include <QComboBox>
#include <QDateTime>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>
#include <QStyle>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>
#include <cmath>

#include "ui/widgets/style.h"

namespace demoplan::ui {

namespace {
// Playback speed at 1x, in joint-space radians per second.
constexpr double kNominalRate = 1.0;
}  // namespace

QStringList waypointActions(const Path& path, const std::vector<std::string>& state_names) {
  QStringList out;
  const auto& w = path.waypoints;
  for (size_t k = 0; k < w.size(); ++k) {
    if (w[k].action == GripperAction::Grasp) {
      out << QStringLiteral("grasp");
      continue;
    }
    if (w[k].action == GripperAction::Release) {
      out << QStringLiteral("release");
      continue;
    }
    if (k + 1 == w.size()) {
      out << QStringLiteral("end");
      continue;
    }
    if (w[k].approach) {
      // A straight move along a handle's axis: towards a grasp, or away after a release.
      const bool toward = k + 1 < w.size() && w[k + 1].action == GripperAction::Grasp;
      const bool after_release = k > 0 && w[k - 1].action == GripperAction::Release;
      out << (toward || !after_release ? QStringLiteral("approach") : QStringLiteral("retreat"));
      continue;
    }
    const std::string& name = !w[k].state_name.empty()
                                  ? w[k].state_name
                                  : (w[k].state >= 0 && w[k].state < int(state_names.size()) ? state_names[w[k].state] : "");
    out << (!name.empty() && name[0] == 'G' ? QStringLiteral("carry") : QStringLiteral("move"));
  }
  return out;
}

ResultPanel::ResultPanel(Document* doc, QWidget* parent) : QWidget(parent), doc_(doc) {
  // Left: verdict, metrics, playback, export. Right: the waypoints.
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(6, 6, 6, 6);
  auto* left = new QVBoxLayout;
  verdict_ = new QLabel(this);
  verdict_->setWordWrap(true);
  verdict_->setTextFormat(Qt::RichText);
  left->addWidget(verdict_);
  metrics_ = new QLabel(this);
  metrics_->setWordWrap(true);
  metrics_->setTextFormat(Qt::RichText);
  left->addWidget(metrics_);
  left->addStretch(1);

  auto* transport = new QHBoxLayout;
  play_ = new QPushButton(this);
  play_->setIcon(style()->standardIcon(QStyle::SP_MediaPlay));
  play_->setToolTip(tr("Play or pause the path (Space while the path is shown)"));
  slider_ = new QSlider(Qt::Horizontal, this);
  slider_->setRange(0, 1000);
  slider_->setToolTip(tr("Scrub along the path"));
  speed_ = new QComboBox(this);
  for (double s : {0.25, 0.5, 1.0, 2.0, 4.0}) speed_->addItem(QStringLiteral("%1×").arg(s), s);
  speed_->setCurrentIndex(3);
  speed_->setToolTip(tr("Playback speed; 1× moves the joints at %1 rad/s").arg(kNominalRate));
  time_ = new QLabel(this);
  time_->setMinimumWidth(80);
  transport->addWidget(play_);
  transport->addWidget(slider_, 1);
  transport->addWidget(time_);
  transport->addWidget(speed_);
  left->addLayout(transport);

  auto* bottom = new QHBoxLayout;
  bottom->addStretch(1);
  export_ = new QPushButton(tr("Export…"), this);
  export_->setToolTip(tr("Write the program for the cell controller"));
  bottom->addWidget(export_);
  left->addLayout(bottom);
  layout->addLayout(left, 3);

  table_ = new QTableWidget(0, 4, this);
  table_->setHorizontalHeaderLabels({tr("#"), tr("Action"), tr("State"), tr("Along")});
  table_->horizontalHeader()->setSectionResizeMode(2, QHeaderView::Stretch);
  table_->verticalHeader()->setVisible(false);
  table_->verticalHeader()->setDefaultSectionSize(20);
  table_->setWordWrap(false);
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->setSelectionMode(QAbstractItemView::SingleSelection);
  table_->setToolTip(tr("The path's waypoints: click one to show the robot there"));
  layout->addWidget(table_, 4);

  timer_ = new QTimer(this);
  timer_->setInterval(30);
  connect(timer_, &QTimer::timeout, this, &ResultPanel::onTick);
  connect(play_, &QPushButton::clicked, this, &ResultPanel::togglePlay);
  connect(slider_, &QSlider::valueChanged, this, [this](int v) { doc_->setPlaybackT(v / 1000.0); });
  connect(table_, &QTableWidget::cellClicked, this, [this](int row, int) {
    if (doc_->planning()->interpolator()) doc_->setPlaybackT(doc_->planning()->interpolator()->waypoint_parameter(size_t(row)));
  });
  connect(export_, &QPushButton::clicked, this, &ResultPanel::exportRequested);
  connect(doc_->planning(), &PlanningController::resultChanged, this, &ResultPanel::refresh);
  connect(doc_, &Document::projectLoaded, this, &ResultPanel::refresh);
  connect(doc_->steps(), &StepStatusModel::changed, this, &ResultPanel::refresh);
  connect(doc_, &Document::displayChanged, this, &ResultPanel::syncSlider);
  refresh();
}

bool ResultPanel::isPlaying() const { return timer_->isActive(); }

void ResultPanel::togglePlay() {
  if (timer_->isActive()) {
    pause();
    return;
  }
  if (!doc_->planning()->interpolator()) return;
  if (doc_->playbackT() >= 1.0 || doc_->displayMode() != Document::DisplayMode::Result) doc_->setPlaybackT(0.0);
  last_tick_ms_ = QDateTime::currentMSecsSinceEpoch();
  timer_->start();
  play_->setIcon(style()->standardIcon(QStyle::SP_MediaPause));
}

void ResultPanel::pause() {
  timer_->stop();
  play_->setIcon(style()->standardIcon(QStyle::SP_MediaPlay));
}

void ResultPanel::onTick() {
  const PathInterpolator* interp = doc_->planning()->interpolator();
  if (!interp || doc_->displayMode() != Document::DisplayMode::Result) {
    pause();
    return;
  }
  const qint64 now = QDateTime::currentMSecsSinceEpoch();
  const double dt = (now - last_tick_ms_) / 1000.0;
  last_tick_ms_ = now;
  const double duration = std::max(1.0, interp->length() / kNominalRate);
  const double t = doc_->playbackT() + dt * speed_->currentData().toDouble() / duration;
  doc_->setPlaybackT(std::min(1.0, t));
  if (t >= 1.0) pause();
}

void ResultPanel::syncSlider() {
  const bool result_mode = doc_->displayMode() == Document::DisplayMode::Result;
  {
    QSignalBlocker b(slider_);
    slider_->setValue(result_mode ? int(std::lround(doc_->playbackT() * 1000)) : 0);
  }
  const PathInterpolator* interp = doc_->planning()->interpolator();
  if (interp) {
    const double duration = std::max(1.0, interp->length() / kNominalRate);
    time_->setText(QStringLiteral("%1 / %2 s").arg(doc_->playbackT() * duration, 0, 'f', 1).arg(duration, 0, 'f', 1));
    // Highlight the segment being played.
    if (result_mode) {
      int row = 0;
      for (int k = 0; k < table_->rowCount(); ++k)
        if (interp->waypoint_parameter(size_t(k)) <= doc_->playbackT() + 1e-9) row = k;
      if (table_->currentRow() != row) {
        QSignalBlocker b(table_);
        table_->selectRow(row);
      }
    }
  } else {
    time_->clear();
  }
  if (!result_mode && timer_->isActive()) pause();
}

void ResultPanel::refresh() {
  const PlanResultData* r = doc_->planning()->result();
  const bool has_path = r && r->path && doc_->planning()->interpolator();
  play_->setEnabled(has_path);
  slider_->setEnabled(has_path);
  speed_->setEnabled(has_path);
  export_->setEnabled(has_path && r->summary.valid);
  if (!r) {
    verdict_->setText(doc_->planning()->runner()->isRunning() ? tr("Planning…") : tr("No result yet: press Plan (F5) in the Planner panel."));
    metrics_->clear();
    table_->setRowCount(0);
    pause();
    return;
  }
  const ResultSummary& s = r->summary;
  QString verdict;
  if (r->cancelled) verdict = tr("<span style='color:%1'><b>Planning cancelled.</b></span>").arg(kWarningColor.name());
  else if (!s.solved)
    verdict = tr("<span style='color:%1'><b>&#10008; No path.</b></span> %2")
                  .arg(kErrorColor.name(), QString::fromStdString(s.message).toHtmlEscaped());
  else if (s.valid)
    verdict = tr("<span style='color:%1'><b>&#10004; Valid path.</b></span> The independent validator (against the %2) "
                 "finds no collision, every part is held or resting, and the start and goal match.")
                  .arg(kOkColor.name(), QString::fromStdString(s.validated_against).toHtmlEscaped());
  else
    verdict = tr("<span style='color:%1'><b>&#9888; The validator rejects the path:</b></span> %2")
                  .arg(kErrorColor.name(), QString::fromStdString(s.message).toHtmlEscaped());
  if (doc_->planning()->resultStale())
    verdict += tr("<br><span style='color:%1'>The demonstration changed since: plan again.</span>").arg(kWarningColor.name());
  verdict_->setText(verdict);
  if (s.solved) {
    metrics_->setText(tr("<table cellspacing=1>"
                         "<tr><td>Planning&nbsp;time&nbsp;</td><td><b>%1 s</b> · %L2 iterations · %3 trees · %L4 nodes</td></tr>"
                         "<tr><td>Robot path</td><td><b>%5 rad</b> in joint space%6</td></tr>"
                         "<tr><td>Parts moved</td><td><b>%7 mm</b>, turned %8°</td></tr>"
                         "<tr><td>Grasps</td><td><b>%9</b></td></tr></table>")
                          .arg(s.planning_time_s, 0, 'f', 2)
                          .arg(s.iterations)
                          .arg(s.trees)
                          .arg(qulonglong(s.nodes))
                          .arg(s.length_robot_rad, 0, 'f', 2)
                          .arg(s.shortened ? tr(", shortened") : QString())
                          .arg(s.length_object_m * 1000, 0, 'f', 0)
                          .arg(s.length_object_rad * 180 / M_PI, 0, 'f', 0)
                          .arg(QString::fromStdString(describe_grasps(s.grasps, s.gripper_closes))));
  } else {
    metrics_->setText(tr("%1 s, %L2 iterations, %3 trees, %L4 nodes")
                          .arg(s.planning_time_s, 0, 'f', 2)
                          .arg(s.iterations)
                          .arg(s.trees)
                          .arg(qulonglong(s.nodes)));
  }
  if (!has_path) {
    table_->setRowCount(0);
    return;
  }
  const Path& path = *r->path;
  const QStringList actions = waypointActions(path, r->state_names);
  table_->setRowCount(int(path.waypoints.size()));
  for (int k = 0; k < int(path.waypoints.size()); ++k) {
    const Waypoint& w = path.waypoints[k];
    QString state = QString::fromStdString(w.state_name);
    if (w.object >= 0 && w.object < int(path.object_ids.size()))
      state += QStringLiteral(" · %1").arg(QString::fromStdString(path.object_ids[w.object]));
    const QStringList cells = {QString::number(k), actions[k], state,
                               QStringLiteral("%1%").arg(doc_->planning()->interpolator()->waypoint_parameter(size_t(k)) * 100, 0, 'f', 0)};
    for (int c = 0; c < 4; ++c) {
      auto* item = table_->item(k, c);
      if (!item) table_->setItem(k, c, item = new QTableWidgetItem);
      item->setText(cells[c]);
    }
    const QString& a = actions[k];
    const QColor color = a == "grasp" ? eventColor(EventType::Grasp)
                         : a == "release" ? eventColor(EventType::Release)
                         : a == "carry" ? QColor(0x1f, 0x6f, 0xeb)
                                        : palette().color(QPalette::Text);
    table_->item(k, 1)->setForeground(color);
  }
  table_->resizeColumnToContents(0);
  table_->resizeColumnToContents(1);
  syncSlider();
}

}  // namespace demoplan::ui
