#include "ui/widgets/placement_panel.h"

#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>
#include <cmath>

#include "core/error.h"
#include "ui/widgets/placement_map_view.h"

namespace demoplan::ui {

namespace {

QDoubleSpinBox* spin(QWidget* parent, double low, double high, int decimals, const QString& suffix, const QString& tip) {
  auto* s = new QDoubleSpinBox(parent);
  s->setRange(low, high);
  s->setDecimals(decimals);
  s->setSingleStep(decimals == 0 ? 15 : 0.05);
  s->setSuffix(suffix);
  s->setToolTip(tip);
  return s;
}

}  // namespace

PlacementPanel::PlacementPanel(Document* doc, QWidget* parent) : QWidget(parent), doc_(doc) {
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(6, 6, 6, 6);
  auto* left = new QVBoxLayout;
  auto* form = new QGridLayout;
  form->setHorizontalSpacing(6);
  form->setVerticalSpacing(3);
  const QString m = QStringLiteral(" m"), deg = QStringLiteral("°");
  const QString where = tr("The region the robot's base may stand in (world frame, the floor grid's metres).");
  x0_ = spin(this, -50, 50, 2, m, where), x1_ = spin(this, -50, 50, 2, m, where);
  y0_ = spin(this, -50, 50, 2, m, where), y1_ = spin(this, -50, 50, 2, m, where);
  const QString turn = tr("The base's yaw range: which way the robot may face (about the vertical).");
  yaw0_ = spin(this, -180, 180, 0, deg, turn), yaw1_ = spin(this, -180, 180, 0, deg, turn);
  int row = 0;
  auto addRange = [&](const QString& label, QDoubleSpinBox* a, QDoubleSpinBox* b) {
    form->addWidget(new QLabel(label, this), row, 0);
    form->addWidget(a, row, 1);
    form->addWidget(new QLabel(tr("to"), this), row, 2);
    form->addWidget(b, row, 3);
    ++row;
  };
  addRange(tr("x"), x0_, x1_);
  addRange(tr("y"), y0_, y1_);
  addRange(tr("Yaw"), yaw0_, yaw1_);
  samples_ = new QSpinBox(this);
  samples_->setRange(1, 5000);
  samples_->setToolTip(tr("Candidate base poses, spread evenly over the region (a Halton sequence). Each is screened "
                          "in milliseconds; those that pass are planned with every seed."));
  seeds_ = new QSpinBox(this);
  seeds_->setRange(1, 20);
  seeds_->setToolTip(tr("Planning runs per candidate that passes the screen (seeds 1..n): the success rate."));
  time_limit_ = spin(this, 0.5, 600, 1, QStringLiteral(" s"), tr("Each planning run stops after this long."));
  form->addWidget(new QLabel(tr("Candidates"), this), row, 0);
  form->addWidget(samples_, row, 1);
  form->addWidget(new QLabel(tr("Seeds"), this), row, 2);
  form->addWidget(seeds_, row, 3);
  ++row;
  form->addWidget(new QLabel(tr("Time limit"), this), row, 0);
  form->addWidget(time_limit_, row, 1);
  left->addLayout(form);

  auto* buttons = new QHBoxLayout;
  search_ = new QPushButton(tr("Search"), this);
  search_->setToolTip(tr("Screen, plan and time every candidate in the background (demoplan-cli place)."));
  cancel_ = new QPushButton(tr("Cancel"), this);
  buttons->addWidget(search_);
  buttons->addWidget(cancel_);
  left->addLayout(buttons);
  progress_ = new QProgressBar(this);
  progress_->setFormat(tr("%v of %m candidates"));
  left->addWidget(progress_);
  summary_ = new QLabel(this);
  summary_->setWordWrap(true);
  left->addWidget(summary_);
  chosen_ = new QLabel(tr("Click a square of the map to choose a base pose (double-click: stand the robot there)."), this);
  chosen_->setWordWrap(true);
  chosen_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  left->addWidget(chosen_);
  stand_ = new QPushButton(tr("Stand the Robot Here and Plan"), this);
  stand_->setToolTip(tr("Moves the robot's base to the chosen candidate (undo restores it) and plans again."));
  left->addWidget(stand_);
  message_ = new QLabel(this);
  message_->setWordWrap(true);
  message_->setStyleSheet(QStringLiteral("color: #b03a2e"));
  left->addWidget(message_);
  left->addStretch(1);
  layout->addLayout(left, 0);
  map_ = new PlacementMapView(doc, this);
  layout->addWidget(map_, 1);

  connect(search_, &QPushButton::clicked, this, &PlacementPanel::search);
  connect(cancel_, &QPushButton::clicked, this, &PlacementPanel::cancel);
  connect(stand_, &QPushButton::clicked, this, &PlacementPanel::standAtChosen);
  connect(map_, &PlacementMapView::chosenChanged, this, &PlacementPanel::refreshChosen);
  connect(map_, &PlacementMapView::standRequested, this, [this] {
    if (stand_->isEnabled()) standAtChosen();
  });
  PlacementSearchJob* job = doc->placement();
  connect(job, &PlacementSearchJob::candidateDone, this, [this](int done, int total) {
    progress_->setRange(0, total);
    progress_->setValue(done);
    refreshSummary();
  });
  connect(job, &PlacementSearchJob::finished, this, [this] {
    setRunning(false);
    refreshSummary();
    // The best is where an operator looks first.
    const PlacementCandidate* best = doc_->placement()->best();
    const auto& all = doc_->placement()->candidates();
    for (size_t i = 0; best && i < all.size(); ++i)
      if (all[i].index == best->index) map_->choose(static_cast<int>(i));
  });
  connect(job, &PlacementSearchJob::cancelled, this, [this] {
    setRunning(false);
    refreshSummary();
  });
  connect(job, &PlacementSearchJob::cleared, this, [this] {
    refreshSummary();
    refreshChosen();
  });
  connect(doc, &Document::projectLoaded, this, &PlacementPanel::loadSettings);
  for (QDoubleSpinBox* s : {x0_, x1_, y0_, y1_, yaw0_, yaw1_, time_limit_})
    connect(s, &QDoubleSpinBox::editingFinished, this, &PlacementPanel::storeSettings);
  for (QSpinBox* s : {samples_, seeds_}) connect(s, &QSpinBox::editingFinished, this, &PlacementPanel::storeSettings);
  loadSettings();
  setRunning(false);
  refreshChosen();
}

void PlacementPanel::loadSettings() {
  const PlacementSearchSettings s = doc_->placement()->settings();
  x0_->setValue(s.region.x.low), x1_->setValue(s.region.x.high);
  y0_->setValue(s.region.y.low), y1_->setValue(s.region.y.high);
  yaw0_->setValue(s.region.yaw.low * 180 / M_PI), yaw1_->setValue(s.region.yaw.high * 180 / M_PI);
  samples_->setValue(s.samples);
  seeds_->setValue(s.seeds);
  time_limit_->setValue(s.time_limit_s);
}

void PlacementPanel::storeSettings() {
  PlacementSearchSettings s = doc_->placement()->settings();
  s.region.x = {x0_->value(), x1_->value()};
  s.region.y = {y0_->value(), y1_->value()};
  s.region.yaw = {yaw0_->value() * M_PI / 180, yaw1_->value() * M_PI / 180};
  s.samples = samples_->value();
  s.seeds = seeds_->value();
  s.time_limit_s = time_limit_->value();
  doc_->placement()->setSettings(s);
  map_->update();
}

void PlacementPanel::search() {
  storeSettings();
  const PlacementSearchSettings s = doc_->placement()->settings();
  if (s.region.x.high <= s.region.x.low || s.region.y.high <= s.region.y.low || s.region.yaw.high < s.region.yaw.low) {
    message_->setText(tr("The region is empty or inverted: each range must go from low to high."));
    return;
  }
  QString error;
  if (!doc_->placement()->start(&error)) {
    message_->setText(error);
    return;
  }
  message_->clear();
  progress_->setRange(0, s.samples);
  progress_->setValue(0);
  setRunning(true);
}

void PlacementPanel::cancel() { doc_->placement()->cancel(); }

void PlacementPanel::standAtChosen() {
  const auto& all = doc_->placement()->candidates();
  const int k = map_->chosen();
  if (k < 0 || k >= static_cast<int>(all.size())) return;
  try {
    doc_->setRobotBase(all[static_cast<size_t>(k)].base);
  } catch (const InputError& e) {
    message_->setText(QString::fromStdString(e.what()));
    return;
  }
  message_->clear();
  if (!doc_->planning()->start()) message_->setText(tr("The robot stands there now; planning did not start (a plan is running?)."));
  map_->update();
}

void PlacementPanel::setRunning(bool running) {
  search_->setEnabled(!running);
  cancel_->setEnabled(running);
  for (QWidget* w : std::initializer_list<QWidget*>{x0_, x1_, y0_, y1_, yaw0_, yaw1_, samples_, seeds_, time_limit_})
    w->setEnabled(!running);
}

void PlacementPanel::refreshSummary() {
  const PlacementSearchJob* job = doc_->placement();
  const auto& all = job->candidates();
  if (all.empty() && !job->isRunning()) {
    summary_->setText(tr("No search yet."));
    return;
  }
  int feasible = 0, planned = 0;
  for (const auto& c : all) feasible += c.feasible, planned += c.usable();
  QString text = tr("%1 of %2 candidates: %3 pass the screen, %4 with a valid plan.")
                     .arg(all.size()).arg(job->total()).arg(feasible).arg(planned);
  if (const PlacementCandidate* best = job->best())
    text += tr(" Best so far: cycle %1 s at x %2, y %3 m, yaw %4°.")
                .arg(*best->cycle_time_s(), 0, 'f', 2).arg(best->base.x, 0, 'f', 2).arg(best->base.y, 0, 'f', 2)
                .arg(best->base.yaw * 180 / M_PI, 0, 'f', 0);
  else if (!job->isRunning() && static_cast<int>(all.size()) == job->total())
    text += tr(" No base pose in the region can do every pick: widen the region or look at the grey squares' reasons.");
  summary_->setText(text);
}

void PlacementPanel::refreshChosen() {
  const QString text = map_->describe(map_->chosen());
  chosen_->setText(text.isEmpty() ? tr("Click a square of the map to choose a base pose (double-click: stand the robot "
                                       "there).")
                                    : text);
  const auto& all = doc_->placement()->candidates();
  const int k = map_->chosen();
  stand_->setEnabled(k >= 0 && k < static_cast<int>(all.size()) && all[static_cast<size_t>(k)].usable());
}

}  // namespace demoplan::ui
