#include "ui/widgets/planner_panel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>

#include "core/planning/planner_registry.h"
#include "ui/widgets/style.h"

namespace demoplan::ui {

PlannerPanel::PlannerPanel(Document* doc, QWidget* parent) : QWidget(parent), doc_(doc) {
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(6, 6, 6, 6);

  // Left: parameters (two columns, so the panel stays short) and buttons.
  auto* left = new QVBoxLayout;
  auto* form = new QGridLayout;
  form->setHorizontalSpacing(6);
  form->setVerticalSpacing(3);
  const PlannerParams defaults;
  int cell = 0;
  auto addField = [&](const QString& label, QWidget* field) {
    auto* l = new QLabel(label, this);
    l->setBuddy(field);
    l->setToolTip(field->toolTip());
    form->addWidget(l, cell / 2, (cell % 2) * 2);
    form->addWidget(field, cell / 2, (cell % 2) * 2 + 1);
    ++cell;
  };
  planner_ = new QComboBox(this);
  for (const PlannerEntry& p : registered_planners()) {
    planner_->addItem(QString::fromStdString(p.name), QString::fromStdString(p.name));
    planner_->setItemData(planner_->count() - 1, QString::fromStdString(p.description), Qt::ToolTipRole);
  }
  planner_->setToolTip(tr("Which planner searches for the path (demoplan-cli plan --planner). \"guided\" roots "
                          "trees at the grasps and releases seen in the video; \"unguided\" searches as HPP does, "
                          "from the start and goal placements only."));
  addField(tr("Planner"), planner_);
  seed_ = new QSpinBox(this);
  seed_->setRange(0, 1'000'000'000);
  seed_->setToolTip(tr("Random seed. The same seed and inputs give the same path, bit for bit; try another seed "
                       "when a run is unlucky. Default %1.").arg(defaults.seed));
  addField(tr("Seed"), seed_);
  time_limit_ = new QDoubleSpinBox(this);
  time_limit_->setRange(0.1, 3600);
  time_limit_->setDecimals(1);
  time_limit_->setSuffix(QStringLiteral(" s"));
  time_limit_->setToolTip(tr("Planning stops after this long without a path. Default %1 s.").arg(defaults.time_limit));
  addField(tr("Time limit"), time_limit_);
  max_iterations_ = new QSpinBox(this);
  max_iterations_->setRange(1, 2'000'000'000);
  max_iterations_->setGroupSeparatorShown(true);
  max_iterations_->setToolTip(tr("Planning stops after this many iterations. Default %L1.").arg(defaults.max_iterations));
  addField(tr("Iterations"), max_iterations_);
  eta_ = new QDoubleSpinBox(this);
  eta_->setRange(0, 1);
  eta_->setDecimals(2);
  eta_->setSingleStep(0.05);
  eta_->setToolTip(tr("Probability, each iteration, of rooting a new tree at a sampled grasp or release seen in "
                      "the video (η in the paper). Higher: more use of the video. Default %1.").arg(defaults.eta_sample_tree));
  addField(tr("Guidance η"), eta_);
  step_ = new QDoubleSpinBox(this);
  step_->setRange(0.01, 5);
  step_->setDecimals(2);
  step_->setSingleStep(0.05);
  step_->setSuffix(QStringLiteral(" rad"));
  step_->setToolTip(tr("How far a tree grows per iteration, in joint space (δ). Default %1 rad.").arg(defaults.step));
  addField(tr("Step δ"), step_);
  resolution_ = new QDoubleSpinBox(this);
  resolution_->setRange(0.001, 0.5);
  resolution_->setDecimals(3);
  resolution_->setSingleStep(0.005);
  resolution_->setSuffix(QStringLiteral(" rad"));
  resolution_->setToolTip(tr("Motions are checked for collisions every this much joint motion (as the validator). "
                             "Smaller is safer and slower. Default %1 rad.").arg(defaults.resolution));
  addField(tr("Resolution"), resolution_);
  regrasp_after_ = new QSpinBox(this);
  regrasp_after_->setRange(0, 2'000'000'000);
  regrasp_after_->setGroupSeparatorShown(true);
  regrasp_after_->setSpecialValueText(tr("never"));
  regrasp_after_->setToolTip(tr("After this many iterations without a path, the guided planner also tries putting "
                                "a part down where the video does not and taking it again (a regrasp), for the "
                                "picks where its search is stuck. 0: never. Default %L1.").arg(defaults.regrasp_after));
  addField(tr("Regrasp after"), regrasp_after_);
  shortcut_ = new QCheckBox(tr("Shorten the path for"), this);
  shortcut_->setToolTip(tr("Replace detours by straight moves where they stay collision-free, after cutting out "
                           "any grasp that only puts a part back where it was; a shortened path that the "
                           "validator rejects is dropped for the original."));
  shortcut_time_ = new QDoubleSpinBox(this);
  shortcut_time_->setRange(0, 60);
  shortcut_time_->setDecimals(1);
  shortcut_time_->setSuffix(QStringLiteral(" s"));
  shortcut_time_->setToolTip(tr("Time spent on straight shortcuts. Default 1 s. Cutting out a put-back grasp "
                                "takes up to 1 s more each."));
  form->addWidget(shortcut_, (cell + 1) / 2, 0, 1, 2);
  form->addWidget(shortcut_time_, (cell + 1) / 2, 2, 1, 1);
  form->setColumnStretch(1, 1);
  form->setColumnStretch(3, 1);
  left->addLayout(form);

  auto* buttons = new QHBoxLayout;
  plan_ = new QPushButton(tr("Plan"), this);
  plan_->setToolTip(tr("Plan a robot motion for the demonstration (F5). Runs in the background."));
  plan_->setDefault(true);
  cancel_ = new QPushButton(tr("Cancel"), this);
  cancel_->setToolTip(tr("Stop planning (Esc)"));
  defaults_ = new QPushButton(tr("Defaults"), this);
  defaults_->setToolTip(tr("Reset every parameter to its default"));
  buttons->addWidget(plan_);
  buttons->addWidget(cancel_);
  buttons->addStretch(1);
  buttons->addWidget(defaults_);
  left->addLayout(buttons);
  progress_ = new QProgressBar(this);
  progress_->setRange(0, 1000);
  progress_->setValue(0);
  progress_->setFormat(tr("idle"));
  progress_->setTextVisible(true);
  left->addWidget(progress_);
  stats_ = new QLabel(this);
  stats_->setText(tr("Not planned yet"));
  left->addWidget(stats_);
  message_ = new QLabel(this);
  message_->setWordWrap(true);
  message_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  left->addWidget(message_);
  left->addStretch(1);
  layout->addLayout(left, 3);

  // Right: nodes per state.
  states_ = new QTableWidget(0, 2, this);
  states_->setHorizontalHeaderLabels({tr("State"), tr("Nodes")});
  states_->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
  states_->horizontalHeader()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
  states_->verticalHeader()->setVisible(false);
  states_->verticalHeader()->setDefaultSectionSize(20);
  states_->setWordWrap(false);
  states_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  states_->setSelectionMode(QAbstractItemView::NoSelection);
  states_->setToolTip(tr("Tree nodes per state of the constraint graph. P: the parts rest where the video shows "
                         "them; G: the robot holds a part by one of its handles. A state that stays at 0 is one "
                         "the planner cannot reach."));
  layout->addWidget(states_, 2);

  for (auto* s : {time_limit_, eta_, step_, resolution_, shortcut_time_})
    connect(s, &QDoubleSpinBox::valueChanged, this, &PlannerPanel::storeSettings);
  connect(seed_, &QSpinBox::valueChanged, this, &PlannerPanel::storeSettings);
  connect(planner_, &QComboBox::currentIndexChanged, this, &PlannerPanel::storeSettings);
  connect(max_iterations_, &QSpinBox::valueChanged, this, &PlannerPanel::storeSettings);
  connect(regrasp_after_, &QSpinBox::valueChanged, this, &PlannerPanel::storeSettings);
  connect(shortcut_, &QCheckBox::toggled, this, &PlannerPanel::storeSettings);
  connect(defaults_, &QPushButton::clicked, this, [this] { doc_->planning()->setSettings(PlannerSettings{}); });
  connect(plan_, &QPushButton::clicked, this, &PlannerPanel::plan);
  connect(cancel_, &QPushButton::clicked, this, &PlannerPanel::cancel);
  connect(doc_->planning(), &PlanningController::settingsChanged, this, &PlannerPanel::loadSettings);
  connect(doc_, &Document::projectLoaded, this, [this] {
    loadSettings();
    onResult();
  });
  connect(doc_->steps(), &StepStatusModel::changed, this, [this] {
    plan_->setEnabled(doc_->hasProject() && !doc_->planning()->runner()->isRunning() && doc_->issues().empty());
    plan_->setToolTip(doc_->issues().empty() ? tr("Plan a robot motion for the demonstration (F5). Runs in the background.")
                                             : tr("Fix the demonstration first: %1")
                                                   .arg(QString::fromStdString(doc_->issues().front().message)));
  });
  PlanRunner* runner = doc_->planning()->runner();
  connect(runner, &PlanRunner::started, this, [this] {
    setRunning(true);
    state_names_.clear();
    states_->setRowCount(0);
    message_->clear();
    progress_->setValue(0);
    progress_->setFormat(tr("building the constraint graph…"));
  });
  connect(runner, &PlanRunner::graphReady, this, [this](std::shared_ptr<const ConstraintGraph> g) {
    state_names_.clear();
    for (const auto& s : g->states) state_names_.push_back(s.name);
    showStates(state_names_, std::vector<size_t>(state_names_.size(), 0));
  });
  connect(runner, &PlanRunner::progress, this, &PlannerPanel::onProgress);
  connect(runner, &PlanRunner::cancelled, this, [this](const PlanSnapshot& s) {
    setRunning(false);
    progress_->setFormat(tr("cancelled after %1 s").arg(s.elapsed_s, 0, 'f', 1));
    message_->setText(tr("Cancelled after %L1 iterations. Press Plan to start again.").arg(s.iterations));
  });
  connect(doc_->planning(), &PlanningController::resultChanged, this, &PlannerPanel::onResult);
  loadSettings();
  setRunning(false);
}

void PlannerPanel::loadSettings() {
  loading_ = true;
  const PlannerSettings& s = doc_->planning()->settings();
  const int planner = planner_->findData(QString::fromStdString(s.planner_name));
  if (planner < 0) {  // a project made with a planner this build does not have
    planner_->addItem(QString::fromStdString(s.planner_name) + tr(" (not available)"), QString::fromStdString(s.planner_name));
    planner_->setCurrentIndex(planner_->count() - 1);
  } else {
    planner_->setCurrentIndex(planner);
  }
  seed_->setValue(int(std::min<std::uint64_t>(s.planner.seed, 1'000'000'000)));
  time_limit_->setValue(s.planner.time_limit);
  max_iterations_->setValue(int(std::min<long>(s.planner.max_iterations, 2'000'000'000)));
  regrasp_after_->setValue(int(std::min<long>(s.planner.regrasp_after, 2'000'000'000)));
  eta_->setValue(s.planner.eta_sample_tree);
  step_->setValue(s.planner.step);
  resolution_->setValue(s.planner.resolution);
  shortcut_->setChecked(s.shortcut);
  shortcut_time_->setValue(s.shortcutting.time_limit);
  shortcut_time_->setEnabled(s.shortcut);
  loading_ = false;
}

void PlannerPanel::storeSettings() {
  if (loading_ || !doc_->hasProject()) return;
  PlannerSettings s = doc_->planning()->settings();
  s.planner_name = planner_->currentData().toString().toStdString();
  s.planner.seed = std::uint64_t(seed_->value());
  s.planner.time_limit = time_limit_->value();
  s.planner.max_iterations = max_iterations_->value();
  s.planner.regrasp_after = regrasp_after_->value();
  s.planner.eta_sample_tree = eta_->value();
  s.planner.step = step_->value();
  s.planner.resolution = resolution_->value();
  s.shortcut = shortcut_->isChecked();
  s.shortcutting.time_limit = shortcut_time_->value();
  shortcut_time_->setEnabled(s.shortcut);
  doc_->planning()->setSettings(s);
}

void PlannerPanel::setRunning(bool running) {
  plan_->setEnabled(!running && doc_->hasProject() && doc_->issues().empty());
  cancel_->setEnabled(running);
  for (QWidget* w : std::initializer_list<QWidget*>{planner_, seed_, time_limit_, max_iterations_, regrasp_after_, eta_, step_, resolution_, shortcut_,
                                                    shortcut_time_, defaults_})
    w->setEnabled(!running);
  if (!running) shortcut_time_->setEnabled(shortcut_->isChecked());
}

void PlannerPanel::plan() {
  if (!doc_->planning()->start()) {
    if (!doc_->issues().empty())
      message_->setText(tr("Cannot plan: %1").arg(QString::fromStdString(doc_->issues().front().message)));
  }
}

void PlannerPanel::cancel() { doc_->planning()->runner()->cancel(); }

void PlannerPanel::showStates(const std::vector<std::string>& names, const std::vector<size_t>& nodes) {
  states_->setUpdatesEnabled(false);
  states_->setRowCount(int(names.size()));
  for (int i = 0; i < int(names.size()); ++i) {
    auto* name = states_->item(i, 0);
    if (!name) {
      name = new QTableWidgetItem;
      states_->setItem(i, 0, name);
      states_->setItem(i, 1, new QTableWidgetItem);
      states_->item(i, 1)->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
    }
    name->setText(QString::fromStdString(names[i]));
    const size_t n = i < int(nodes.size()) ? nodes[i] : 0;
    states_->item(i, 1)->setText(QString::number(n));
    const QBrush bg = n == 0 ? QBrush(QColor(0xff, 0xf1, 0xd6)) : QBrush();
    name->setBackground(bg);
    states_->item(i, 1)->setBackground(bg);
    name->setToolTip(n == 0 ? tr("No node here yet: the planner has not reached this state") : QString());
  }
  states_->setUpdatesEnabled(true);
}

void PlannerPanel::onProgress(const PlanSnapshot& s) {
  const double limit = doc_->planning()->settings().planner.time_limit;
  progress_->setValue(int(std::min(1.0, s.elapsed_s / std::max(1e-9, limit)) * 1000));
  progress_->setFormat(tr("planning… %1 s of at most %2 s").arg(s.elapsed_s, 0, 'f', 1).arg(limit, 0, 'f', 0));
  stats_->setText(tr("%1 s · %L2 iterations · %3 trees · %L4 nodes")
                      .arg(s.elapsed_s, 0, 'f', 2)
                      .arg(s.iterations)
                      .arg(s.trees)
                      .arg(qulonglong(s.nodes)));
  if (!s.state_names.empty()) showStates(s.state_names, s.state_nodes);
  else if (!state_names_.empty()) showStates(state_names_, s.state_nodes);
}

void PlannerPanel::onResult() {
  const PlanResultData* r = doc_->planning()->result();
  setRunning(doc_->planning()->runner()->isRunning());
  if (doc_->planning()->runner()->isRunning()) return;
  if (!r) {
    progress_->setValue(0);
    progress_->setFormat(tr("idle"));
    stats_->setText(tr("Not planned yet"));
    message_->clear();
    states_->setRowCount(0);
    return;
  }
  const ResultSummary& s = r->summary;
  if (r->cancelled) return;  // the cancel handler said it
  progress_->setValue(1000);
  progress_->setFormat(s.solved ? tr("solved in %1 s").arg(s.planning_time_s, 0, 'f', 2) : tr("no path"));
  stats_->setText(tr("%1 s · %L2 iterations · %3 trees · %L4 nodes")
                      .arg(s.planning_time_s, 0, 'f', 2)
                      .arg(s.iterations)
                      .arg(s.trees)
                      .arg(qulonglong(s.nodes)));
  if (!r->state_names.empty()) showStates(r->state_names, r->state_nodes);
  QString msg;
  if (!s.solved) {
    msg = tr("<span style='color:%1'><b>No path.</b></span> %2").arg(kErrorColor.name(), QString::fromStdString(s.message).toHtmlEscaped());
    if (!r->infeasible_picks.empty()) {
      QStringList picks;
      for (const auto& line : QString::fromStdString(r->infeasible_picks).split('\n', Qt::SkipEmptyParts))
        picks << line.toHtmlEscaped();
      msg += tr("<br><b>The demonstration cannot be done from this robot base pose</b> — move the part or the "
                "robot, or correct the pose at that event:<br>&nbsp;&nbsp;%1")
                 .arg(picks.join(QStringLiteral("<br>&nbsp;&nbsp;")));
    } else if (!r->unsampled_transitions.empty()) {
      QStringList names;
      for (const auto& t : r->unsampled_transitions) names << QString::fromStdString(t).toHtmlEscaped();
      msg += tr("<br>These transitions were never sampled without a collision — the grasp or placement they need "
                "may be unreachable or inside furniture; check the part's pose there:<br>&nbsp;&nbsp;%1")
                 .arg(names.join(QStringLiteral("<br>&nbsp;&nbsp;")));
    }
    const auto zero = std::count(r->state_nodes.begin(), r->state_nodes.end(), size_t(0));
    if (zero > 0) msg += tr("<br>%1 state(s) have no node (highlighted in the table).").arg(zero);
  } else if (!s.valid) {
    msg = tr("<span style='color:%1'><b>Path found but the validator rejects it:</b></span> %2")
              .arg(kWarningColor.name(), QString::fromStdString(s.message).toHtmlEscaped());
  } else {
    msg = tr("<span style='color:%1'><b>Path found and valid.</b></span> See the Result panel.").arg(kOkColor.name());
  }
  if (s.solved && !r->regrasp.empty())
    msg += tr("<br>The demonstration could not be done holding the part one way; the path adds a regrasp: %1.")
               .arg(QString::fromStdString(r->regrasp).toHtmlEscaped());
  if (!r->shortcut_note.empty()) msg += QStringLiteral("<br>") + QString::fromStdString(r->shortcut_note).toHtmlEscaped();
  message_->setText(msg);
}

}  // namespace demoplan::ui
