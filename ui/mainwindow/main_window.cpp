#include "ui/mainwindow/main_window.h"

#include <filesystem>

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QComboBox>
#include <QCryptographicHash>
#include <QDateTime>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDir>
#include <QDockWidget>
#include <QInputDialog>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QStandardPaths>
#include <QStatusBar>
#include <QStyle>
#include <QTimer>
#include <QToolBar>
#include <QUndoView>

#include "core/cell/cell_edits.h"
#include "core/demo/benchmark_scene.h"
#include "core/error.h"
#include "ui/view3d/scene_view.h"
#include "ui/widgets/calibration_dialog.h"
#include "ui/widgets/cell_panel.h"
#include "ui/widgets/export_dialog.h"
#include "ui/widgets/part_tracks_panel.h"
#include "ui/widgets/placement_panel.h"
#include "ui/widgets/planner_panel.h"
#include "ui/widgets/pose_editor.h"
#include "ui/widgets/result_panel.h"
#include "ui/widgets/step_bar.h"
#include "ui/widgets/style.h"
#include "ui/widgets/timeline_widget.h"
#include "ui/widgets/transport.h"
#include "ui/widgets/video_panel.h"

namespace demoplan::ui {

namespace {
constexpr int kMaxRecent = 8;
const char* const kProjectFilter = QT_TRANSLATE_NOOP("MainWindow", "demoplan projects (*.demoplan);;All files (*)");

QString humanAge(qint64 ms) {
  const qint64 s = ms / 1000;
  if (s < 60) return MainWindow::tr("%1 s ago").arg(s);
  if (s < 3600) return MainWindow::tr("%1 min ago").arg(s / 60);
  return MainWindow::tr("%1 h ago").arg(s / 3600);
}
}  // namespace

MainWindow::MainWindow(MainWindowOptions options, QWidget* parent)
    : QMainWindow(parent), options_(std::move(options)) {
  setObjectName(QStringLiteral("MainWindow"));
  setAcceptDrops(true);
  setDockOptions(AnimatedDocks | AllowTabbedDocks | AllowNestedDocks);
  doc_ = new Document(options_.data_dir, this);
  transport_ = new Transport(doc_, this);
  scene_view_ = new SceneView(doc_, this);
  setCentralWidget(scene_view_);
  createDocks();
  createActions();

  frame_label_ = new QLabel(this);
  saved_label_ = new QLabel(this);
  statusBar()->addPermanentWidget(frame_label_);
  statusBar()->addPermanentWidget(saved_label_);

  connect(doc_, &Document::fileChanged, this, &MainWindow::updateTitle);
  connect(doc_, &Document::modifiedChanged, this, &MainWindow::updateTitle);
  connect(doc_->steps(), &StepStatusModel::changed, this, &MainWindow::updateSteps);
  connect(doc_, &Document::currentFrameChanged, this, &MainWindow::updateStatus);
  connect(doc_, &Document::displayChanged, this, &MainWindow::updateStatus);
  connect(doc_, &Document::saved, this, [this] {
    saved_at_ms_ = QDateTime::currentMSecsSinceEpoch();
    updateStatus();
  });
  connect(doc_, &Document::projectLoaded, this, [this] {
    saved_at_ms_ = doc_->filePath().isEmpty() ? 0 : QFileInfo(doc_->filePath()).lastModified().toMSecsSinceEpoch();
    updateSteps();
    updateStatus();
  });
  connect(doc_->planning()->runner(), &PlanRunner::progress, this, [this] { updateSteps(); });
  connect(scene_view_, &SceneView::objectPicked, this, [this](int o) {
    if (o >= 0) {
      inspector_dock_->raise();
      statusBar()->showMessage(tr("Selected %1: edit its pose in the Inspector or drag the gizmo")
                                   .arg(QString::fromStdString(doc_->demonstration().object_ids[o])),
                               5000);
    }
  });
  connect(step_bar_, &StepBar::stepClicked, this, &MainWindow::showStep);
  // The step bar follows the panel the operator works in.
  connect(qApp, &QApplication::focusChanged, this, [this](QWidget*, QWidget* now) {
    for (QWidget* w = now; w; w = w->parentWidget()) {
      if (w == video_dock_) return step_bar_->setCurrent(Step::Video);
      if (w == timeline_dock_ || w == tracks_dock_) return step_bar_->setCurrent(Step::Events);
      if (w == inspector_dock_) return step_bar_->setCurrent(Step::Poses);
      if (w == planner_dock_ || w == result_dock_) return step_bar_->setCurrent(Step::Plan);
      if (qobject_cast<ExportDialog*>(w)) return step_bar_->setCurrent(Step::Export);
    }
  });
  connect(doc_->planning()->runner(), &PlanRunner::started, this, [this] { step_bar_->setCurrent(Step::Plan); });
  connect(result_, &ResultPanel::exportRequested, this, [this] { export_action_->trigger(); });

  autosave_timer_ = new QTimer(this);
  autosave_timer_->setInterval(options_.autosave_interval_ms);
  connect(autosave_timer_, &QTimer::timeout, this, &MainWindow::autosaveNow);
  autosave_timer_->start();
  status_timer_ = new QTimer(this);
  status_timer_->setInterval(1000);
  connect(status_timer_, &QTimer::timeout, this, &MainWindow::updateStatus);
  status_timer_->start();

  resize(1280, 800);
  default_state_ = saveState();
  if (options_.restore_layout) {
    QSettings settings;
    restoreGeometry(settings.value(QStringLiteral("window/geometry")).toByteArray());
    restoreState(settings.value(QStringLiteral("window/state")).toByteArray());
  }
  updateTitle();
  updateSteps();
  updateStatus();
  updateRecentMenu();
}

MainWindow::~MainWindow() = default;

QDockWidget* MainWindow::addDock(const QString& title, const QString& name, QWidget* widget, Qt::DockWidgetArea area) {
  auto* dock = new QDockWidget(title, this);
  dock->setObjectName(name);  // the key QSettings restores the layout by
  dock->setWidget(widget);
  dock->setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetFloatable | QDockWidget::DockWidgetClosable);
  addDockWidget(area, dock);
  return dock;
}

void MainWindow::createDocks() {
  setCorner(Qt::BottomLeftCorner, Qt::BottomDockWidgetArea);
  setCorner(Qt::BottomRightCorner, Qt::BottomDockWidgetArea);
  video_ = new VideoPanel(doc_, transport_, this);
  connect(video_, &VideoPanel::openVideoRequested, this, [this] { openVideo(); });
  video_dock_ = addDock(tr("Video"), QStringLiteral("VideoDock"), video_, Qt::LeftDockWidgetArea);
  timeline_ = new TimelinePanel(doc_, this);
  timeline_dock_ = addDock(tr("Timeline"), QStringLiteral("TimelineDock"), timeline_, Qt::BottomDockWidgetArea);
  pose_editor_ = new PoseEditor(doc_, this);
  inspector_dock_ = addDock(tr("Inspector"), QStringLiteral("InspectorDock"), pose_editor_, Qt::BottomDockWidgetArea);
  planner_ = new PlannerPanel(doc_, this);
  planner_dock_ = addDock(tr("Planner"), QStringLiteral("PlannerDock"), planner_, Qt::BottomDockWidgetArea);
  result_ = new ResultPanel(doc_, this);
  result_dock_ = addDock(tr("Result"), QStringLiteral("ResultDock"), result_, Qt::BottomDockWidgetArea);
  part_tracks_ = new PartTracksPanel(doc_, this);
  tracks_dock_ = addDock(tr("Part Tracks"), QStringLiteral("PartTracksDock"), part_tracks_, Qt::BottomDockWidgetArea);
  cell_panel_ = new CellPanel(doc_, this);
  cell_dock_ = addDock(tr("Cell"), QStringLiteral("CellDock"), cell_panel_, Qt::LeftDockWidgetArea);
  connect(scene_view_, &SceneView::editRefused, this,
          [this](const QString& reason) { statusBar()->showMessage(reason, 10000); });
  // A click on a cell's furniture chooses it in the Cell panel (and gives it the gizmo).
  connect(scene_view_, &SceneView::furniturePicked, this, [this](int f) {
    const Cell* cell = doc_->cell();
    if (!cell) return;
    const std::string& name = doc_->scene().furniture.at(static_cast<size_t>(f)).name;
    for (size_t k = 0; k < cell->furniture.size(); ++k)
      if (cell->furniture[k].name == name) {
        cell_dock_->raise();
        cell_panel_->select(CellPanel::Kind::Furniture, static_cast<int>(k));
        statusBar()->showMessage(tr("Selected %1: drag the gizmo or type its pose in the Cell panel")
                                     .arg(QString::fromStdString(name)), 5000);
        return;
      }
  });
  // Stick Markers: a click on a part's face in the 3D view sticks a marker there.
  connect(scene_view_, &SceneView::surfacePicked, this, [this](const SceneView::SurfaceHit& hit) {
    const Cell* cell = doc_->cell();
    if (!cell || !cell_panel_->stickingMarkers()) return;
    const std::string& name = doc_->scene().objects.at(static_cast<size_t>(hit.object)).id;
    for (size_t p = 0; p < cell->parts.size(); ++p)
      if (cell->parts[p].name == name) {
        cell_dock_->raise();
        cell_panel_->stickMarker(static_cast<int>(p), hit.point, hit.normal);
        return;
      }
  });
  placement_ = new PlacementPanel(doc_, this);
  placement_dock_ = addDock(tr("Placement"), QStringLiteral("PlacementDock"), placement_, Qt::BottomDockWidgetArea);
  history_ = new QUndoView(doc_->undoStack(), this);
  history_->setEmptyLabel(tr("<opened>"));
  history_dock_ = addDock(tr("History"), QStringLiteral("HistoryDock"), history_, Qt::BottomDockWidgetArea);
  splitDockWidget(timeline_dock_, inspector_dock_, Qt::Vertical);
  // Under the timeline, the same width, so its frames line up with the timeline's.
  splitDockWidget(timeline_dock_, tracks_dock_, Qt::Vertical);
  splitDockWidget(inspector_dock_, planner_dock_, Qt::Horizontal);
  tabifyDockWidget(planner_dock_, result_dock_);
  tabifyDockWidget(result_dock_, placement_dock_);
  tabifyDockWidget(placement_dock_, history_dock_);
  tabifyDockWidget(video_dock_, cell_dock_);
  planner_dock_->raise();
  video_dock_->raise();
  // The cell editor is there on a project on a cell, in front until a video is opened.
  connect(doc_, &Document::projectLoaded, this, [this] {
    const bool cell = doc_->cell() != nullptr;
    cell_dock_->setVisible(cell);
    if (cell && doc_->media()->videoFile().empty()) cell_dock_->raise();
  });
  cell_dock_->hide();
  resizeDocks({video_dock_}, {470}, Qt::Horizontal);
  resizeDocks({inspector_dock_, planner_dock_}, {330, 950}, Qt::Horizontal);
  resizeDocks({timeline_dock_, inspector_dock_}, {118, 236}, Qt::Vertical);
  // Shown by Detect Events from Tracks (or View > Part Tracks): the video workflow keeps its room.
  tracks_dock_->hide();
  // Plan brings the planner forward; a finished plan its result.
  connect(doc_->planning()->runner(), &PlanRunner::started, this, [this] {
    planner_dock_->show();
    planner_dock_->raise();
  });
  connect(doc_->planning()->runner(), &PlanRunner::finished, this, [this] {
    result_dock_->show();
    result_dock_->raise();
  });
}

void MainWindow::createActions() {
  QStyle* st = style();
  // ---- File
  QMenu* file = menuBar()->addMenu(tr("&File"));
  auto* new_action = file->addAction(tr("&New from Benchmark Task…"), this, &MainWindow::newFromBenchmarkDialog);
  new_action->setShortcut(QKeySequence::New);
  new_action->setStatusTip(tr("Start a project from a task of the bundled benchmark (scene and labelled events)"));
  auto* new_cell = file->addAction(tr("New from &Cell…"), this, [this] {
    if (!maybeSave()) return;
    const QString dir = QString::fromStdString((std::filesystem::path(options_.data_dir) / ".." / "cells").lexically_normal().string());
    const QString f = QFileDialog::getOpenFileName(this, tr("New project on a cell"), dir, tr("Cell files (*.json)"));
    if (!f.isEmpty()) newFromCell(f);
  });
  new_cell->setShortcut(QKeySequence(tr("Ctrl+Shift+N")));
  auto* make_cell = file->addAction(tr("New &Cell…"), this, &MainWindow::newCellDialog);
  make_cell->setStatusTip(tr("Set up your own cell: choose the robot, then add furniture and parts from their files "
                             "in the Cell panel"));
  new_cell->setStatusTip(tr("Start a project on your own cell: robot, furniture and parts from files (docs/cell.md)"));
  auto* open = file->addAction(st->standardIcon(QStyle::SP_DialogOpenButton), tr("&Open…"), this, [this] {
    if (!maybeSave()) return;
    QSettings settings;
    const QString f = QFileDialog::getOpenFileName(this, tr("Open project"), settings.value("lastDir").toString(),
                                                   tr(kProjectFilter));
    if (!f.isEmpty()) openProject(f);
  });
  open->setShortcut(QKeySequence::Open);
  recent_menu_ = file->addMenu(tr("Open &Recent"));
  file->addAction(tr("Open the &Sample Project"), this, &MainWindow::openSample);
  file->addSeparator();
  save_action_ = file->addAction(st->standardIcon(QStyle::SP_DialogSaveButton), tr("&Save"), this, &MainWindow::save);
  save_action_->setShortcut(QKeySequence::Save);
  auto* save_as = file->addAction(tr("Save &As…"), this, [this] { saveAs(); });
  save_as->setShortcut(QKeySequence(QStringLiteral("Ctrl+Shift+S")));
  file->addSeparator();
  auto* video = file->addAction(tr("Open &Video…"), this, [this] { openVideo(); });
  video->setStatusTip(tr("Open the recording of the demonstration (or drop it on the window)"));
  file->addAction(tr("Open &Camera Calibration…"), this, [this] { openCamera(); });
  auto* calibrate = file->addAction(tr("Ca&librate Camera…"), this, [this] {
    CalibrationDialog dialog(doc_, this);
    dialog.exec();
  });
  calibrate->setStatusTip(tr("The camera's intrinsics from a video of a printed ChArUco board: progress, the error of "
                             "every view, then use it for this project"));
  file->addAction(tr("Open &Marker Scene…"), this, [this] {
    if (!doc_->hasProject()) return;
    const QString f = QFileDialog::getOpenFileName(this, tr("Open marker scene"), QFileInfo(doc_->filePath()).absolutePath(),
                                                   tr("Marker scenes (*.json);;All files (*)"));
    if (!f.isEmpty()) doc_->setMediaFile(Media::File::Markers, f);
  })->setStatusTip(tr("Which ArUco markers are on which part: needed to detect the events in the video"));
  file->addSeparator();
  export_action_ = file->addAction(tr("&Export Program…"), this, [this] { showExportDialog(); });
  export_action_->setShortcut(QKeySequence(QStringLiteral("Ctrl+E")));
  export_action_->setStatusTip(tr("Write the planned path as a program for the cell controller (UR, KUKA, Franka, ROS, CSV)"));
  file->addSeparator();
  auto* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
  quit->setShortcut(QKeySequence::Quit);

  // ---- Edit
  QMenu* edit = menuBar()->addMenu(tr("&Edit"));
  QAction* undo = doc_->undoStack()->createUndoAction(this, tr("&Undo"));
  undo->setShortcut(QKeySequence::Undo);
  undo->setIcon(st->standardIcon(QStyle::SP_ArrowBack));
  undo->setIconText(tr("Undo"));  // the menu says what; the toolbar stays short
  QAction* redo = doc_->undoStack()->createRedoAction(this, tr("&Redo"));
  redo->setShortcuts({QKeySequence(QStringLiteral("Ctrl+Shift+Z")), QKeySequence(QStringLiteral("Ctrl+Y"))});
  redo->setIcon(st->standardIcon(QStyle::SP_ArrowForward));
  redo->setIconText(tr("Redo"));
  edit->addAction(undo);
  edit->addAction(redo);
  edit->addSeparator();
  auto* add_grasp = edit->addAction(tr("Add &Grasp at Playhead"), this, [this] { addEventAtPlayhead(EventType::Grasp); });
  add_grasp->setShortcut(QKeySequence(Qt::Key_G));
  add_grasp->setStatusTip(tr("Add a grasp of the selected part at the current frame"));
  auto* add_release =
      edit->addAction(tr("Add &Release at Playhead"), this, [this] { addEventAtPlayhead(EventType::Release); });
  add_release->setShortcut(QKeySequence(Qt::Key_R));
  delete_action_ = edit->addAction(tr("&Delete Event"), this, [this] {
    if (doc_->selectedEvent() >= 0) doc_->removeEvent(doc_->selectedEvent());
  });
  delete_action_->setShortcuts({QKeySequence(Qt::Key_Delete), QKeySequence(Qt::Key_Backspace)});
  auto* detect = edit->addAction(tr("Detect &Events in the Video"), this, [this] {
    timeline_dock_->show();
    timeline_dock_->raise();
    if (!doc_->detection()->start()) reportError(tr("Detect events"), doc_->detection()->blocker());
  });
  detect->setShortcut(QKeySequence(QStringLiteral("Ctrl+D")));
  track_detect_action_ = edit->addAction(tr("Detect Events from &Tracks"), this, &MainWindow::detectEventsFromTracks);
  track_detect_action_->setShortcut(QKeySequence(QStringLiteral("Ctrl+Shift+D")));
  track_detect_action_->setStatusTip(tr("Find the grasps and releases from the benchmark task's pose tracks alone (no labels); "
                                        "the Part Tracks panel shows why each is where it is. Undo brings the old events back."));
  edit->addSeparator();
  auto* place_again = edit->addAction(tr("&Place Part Again Here"), this, &MainWindow::placePartAgain);
  place_again->setShortcut(QKeySequence(QStringLiteral("Ctrl+Shift+P")));
  place_again->setStatusTip(tr("Where the part-model tracker lost the selected part or followed it wrongly: place it "
                               "again over this frame, and Detect Events follows it from there"));
  auto* from_estimates = edit->addAction(tr("Place Parts &from Pose Estimates..."), this, &MainWindow::placeStartsFromEstimates);
  from_estimates->setStatusTip(tr("Start every part where a 6D pose estimator's results (BOP CSV) show it in frame 0, "
                                  "instead of moving each there; the part-model tracker starts from these poses"));
  auto* remove_placement = edit->addAction(tr("Remove This Placement"), this, [this] {
    doc_->removeCorrection(doc_->correctionAt(doc_->selectedObject(), doc_->currentFrame()));
  });
  auto update_placement = [this, place_again, remove_placement] {
    const int object = doc_->hasProject() ? doc_->selectedObject() : -1;
    place_again->setEnabled(object >= 0 && doc_->currentFrame() > 0);
    remove_placement->setEnabled(doc_->correctionAt(object, doc_->currentFrame()) >= 0);
  };
  connect(doc_, &Document::selectionChanged, this, update_placement);
  connect(doc_, &Document::currentFrameChanged, this, update_placement);
  connect(doc_, &Document::correctionsChanged, this, update_placement);
  connect(doc_, &Document::projectLoaded, this, update_placement);
  update_placement();
  edit->addSeparator();
  auto* next_issue = edit->addAction(tr("Go to the &Broken Rule"), this, [this] { timeline_->jumpToIssue(0); });
  next_issue->setShortcut(QKeySequence(QStringLiteral("Ctrl+J")));
  auto* next_doubt = edit->addAction(tr("Go to the Next D&oubt"), this, [this] {
    if (timeline_->jumpToNextDoubt() < 0) statusBar()->showMessage(tr("No detection doubts"), 3000);
  });
  next_doubt->setShortcut(QKeySequence(QStringLiteral("Ctrl+Shift+J")));
  next_doubt->setStatusTip(tr("Move the playhead to the next frame range the event detection could not decide"));

  // ---- View
  view_menu_ = menuBar()->addMenu(tr("&View"));
  auto* fit = view_menu_->addAction(tr("&Fit 3D View"), scene_view_, &SceneView::fitToScene);
  fit->setShortcut(QKeySequence(Qt::Key_F));
  auto* trees = view_menu_->addAction(tr("Show Planner &Trees"));
  trees->setCheckable(true);
  trees->setChecked(true);
  trees->setShortcut(QKeySequence(Qt::Key_T));
  connect(trees, &QAction::toggled, scene_view_, &SceneView::setShowTrees);
  auto* demo_view = view_menu_->addAction(tr("Show the &Demonstration"), doc_, &Document::showDemonstration);
  demo_view->setStatusTip(tr("Show the parts where the video puts them at the playhead"));
  auto* path_view = view_menu_->addAction(tr("Show the Planned &Path"), this, [this] { doc_->setPlaybackT(doc_->playbackT()); });
  path_view->setStatusTip(tr("Show the robot and the parts along the planned path"));
  view_menu_->addSeparator();
  for (QDockWidget* d : {video_dock_, cell_dock_, timeline_dock_, tracks_dock_, inspector_dock_, planner_dock_, result_dock_,
                         placement_dock_, history_dock_})
    view_menu_->addAction(d->toggleViewAction());
  view_menu_->addSeparator();
  view_menu_->addAction(tr("&Reset Layout"), this, [this] { restoreState(default_state_); });

  // ---- Playback
  QMenu* play = menuBar()->addMenu(tr("&Playback"));
  auto add = [&](QMenu* menu, const QString& text, const QKeySequence& key, auto slot) {
    QAction* a = menu->addAction(text, this, slot);
    a->setShortcut(key);
    return a;
  };
  add(play, tr("Play / Pause"), QKeySequence(Qt::Key_Space), [this] {
    if (doc_->displayMode() == Document::DisplayMode::Result && doc_->planning()->interpolator()) result_->togglePlay();
    else transport_->toggle();
  });
  add(play, tr("One Frame Back"), QKeySequence(Qt::Key_Left), [this] { transport_->stepFrames(-1); });
  add(play, tr("One Frame Forward"), QKeySequence(Qt::Key_Right), [this] { transport_->stepFrames(1); });
  add(play, tr("One Second Back"), QKeySequence(Qt::SHIFT | Qt::Key_Left), [this] { transport_->stepSeconds(-1); });
  add(play, tr("One Second Forward"), QKeySequence(Qt::SHIFT | Qt::Key_Right), [this] { transport_->stepSeconds(1); });
  add(play, tr("Play Backward (J)"), QKeySequence(Qt::Key_J), [this] { transport_->j(); });
  add(play, tr("Pause (K)"), QKeySequence(Qt::Key_K), [this] {
    transport_->k();
    result_->pause();
  });
  add(play, tr("Play Forward (L)"), QKeySequence(Qt::Key_L), [this] { transport_->l(); });
  add(play, tr("First Frame"), QKeySequence(Qt::Key_Home), [this] { transport_->home(); });
  add(play, tr("Last Frame"), QKeySequence(Qt::Key_End), [this] { transport_->end(); });

  // ---- Plan
  QMenu* plan = menuBar()->addMenu(tr("P&lan"));
  plan_action_ = add(plan, tr("&Plan"), QKeySequence(Qt::Key_F5), [this] {
    planner_dock_->show();
    planner_dock_->raise();
    planner_->plan();
  });
  plan_action_->setIcon(st->standardIcon(QStyle::SP_MediaPlay));
  plan_action_->setToolTip(tr("Plan the robot motion in the background (F5)"));
  cancel_action_ = add(plan, tr("&Cancel Planning"), QKeySequence(Qt::Key_Escape), [this] { planner_->cancel(); });
  cancel_action_->setIcon(st->standardIcon(QStyle::SP_BrowserStop));
  cancel_action_->setEnabled(false);
  connect(doc_->planning()->runner(), &PlanRunner::started, this, [this] { cancel_action_->setEnabled(true); });
  connect(doc_->planning()->runner(), &PlanRunner::finished, this, [this] { cancel_action_->setEnabled(false); });
  connect(doc_->planning()->runner(), &PlanRunner::cancelled, this, [this] { cancel_action_->setEnabled(false); });
  plan->addSeparator();
  add(plan, tr("&Where to Put the Robot..."), QKeySequence(), [this] {
    placement_dock_->show();
    placement_dock_->raise();
  })->setStatusTip(tr("Search the robot's base pose for this task: a heat map of cycle times (demoplan-cli place)"));

  // ---- Help
  QMenu* help = menuBar()->addMenu(tr("&Help"));
  help->addAction(tr("&Keyboard Shortcuts"), this, &MainWindow::showShortcuts)->setShortcut(QKeySequence::HelpContents);
  help->addAction(tr("&About demoplan"), this, &MainWindow::showAbout);

  // ---- Toolbar and step bar
  QToolBar* tools = addToolBar(tr("Main"));
  tools->setObjectName(QStringLiteral("MainToolBar"));
  tools->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
  tools->setIconSize(QSize(16, 16));
  tools->addAction(open);
  tools->addAction(save_action_);
  tools->addSeparator();
  tools->addAction(undo);
  tools->addAction(redo);
  tools->addSeparator();
  tools->addAction(plan_action_);
  tools->addAction(cancel_action_);
  QToolBar* steps = addToolBar(tr("Steps"));
  steps->setObjectName(QStringLiteral("StepsToolBar"));
  step_bar_ = new StepBar(this);
  steps->addWidget(step_bar_);
}

// --------------------------------------------------------------------------------- state

void MainWindow::updateTitle() {
  QString name = doc_->displayName();
  if (doc_->isTemplate()) name += tr(" (sample: Save As to keep your changes)");
  setWindowTitle(QStringLiteral("%1[*] — demoplan").arg(name));
  setWindowModified(doc_->isModified());
  save_action_->setEnabled(doc_->hasProject());
  track_detect_action_->setEnabled(doc_->trackDetection()->blocker().isEmpty());
}

void MainWindow::updateSteps() {
  for (int i = 0; i < 5; ++i) step_bar_->setState(Step(i), doc_->steps()->state(Step(i)));
  if (doc_->planning()->runner()->isRunning()) {
    const PlanSnapshot& s = doc_->planning()->runner()->lastSnapshot();
    step_bar_->setState(Step::Plan, {StepStatus::Busy, tr("Planning… %1 s, %L2 nodes").arg(s.elapsed_s, 0, 'f', 1).arg(qulonglong(s.nodes))});
  }
  export_action_->setEnabled(doc_->hasProject() && doc_->planning()->result() && doc_->planning()->result()->path && !doc_->planning()->runner()->isRunning());
}

void MainWindow::updateStatus() {
  if (!doc_->hasProject()) {
    frame_label_->clear();
    saved_label_->clear();
    return;
  }
  if (doc_->displayMode() == Document::DisplayMode::Result)
    frame_label_->setText(tr("path %1%").arg(doc_->playbackT() * 100, 0, 'f', 0));
  else
    frame_label_->setText(tr("frame %1/%2 · %3 s")
                              .arg(doc_->currentFrame())
                              .arg(doc_->frameCount() - 1)
                              .arg(doc_->currentFrame() / doc_->fps(), 0, 'f', 1));
  const qint64 now = QDateTime::currentMSecsSinceEpoch();
  QString saved;
  if (doc_->filePath().isEmpty() || doc_->isTemplate()) saved = tr("not saved yet");
  else if (saved_at_ms_ > 0) saved = tr("project saved %1").arg(humanAge(now - saved_at_ms_));
  if (doc_->isModified()) saved += tr(" · unsaved changes");
  saved_label_->setText(saved);
}

QStringList MainWindow::recentFiles() const { return QSettings().value(QStringLiteral("recentFiles")).toStringList(); }

void MainWindow::addRecentFile(const QString& file) {
  QSettings settings;
  QStringList files = settings.value(QStringLiteral("recentFiles")).toStringList();
  const QString abs = QFileInfo(file).absoluteFilePath();
  files.removeAll(abs);
  files.prepend(abs);
  while (files.size() > kMaxRecent) files.removeLast();
  settings.setValue(QStringLiteral("recentFiles"), files);
  settings.setValue(QStringLiteral("lastDir"), QFileInfo(abs).absolutePath());
  updateRecentMenu();
}

void MainWindow::updateRecentMenu() {
  recent_menu_->clear();
  const QStringList files = recentFiles();
  for (int i = 0; i < files.size(); ++i) {
    QAction* a = recent_menu_->addAction(QStringLiteral("&%1 %2").arg(i + 1).arg(QFileInfo(files[i]).fileName()), this,
                                         [this, f = files[i]] {
                                           if (maybeSave()) openProject(f);
                                         });
    a->setStatusTip(files[i]);
  }
  recent_menu_->setEnabled(!files.isEmpty());
  if (!files.isEmpty()) {
    recent_menu_->addSeparator();
    recent_menu_->addAction(tr("Clear the List"), this, [this] {
      QSettings().remove(QStringLiteral("recentFiles"));
      updateRecentMenu();
    });
  }
}

void MainWindow::reportError(const QString& title, const QString& message) {
  last_error_ = message;
  statusBar()->showMessage(message, 15000);
  if (options_.interactive) QMessageBox::critical(this, title, message);
}

void MainWindow::showStep(Step step) {
  step_bar_->setCurrent(step);
  auto bring = [](QDockWidget* d) {
    d->show();
    d->raise();
  };
  switch (step) {
    case Step::Video:
      bring(video_dock_);
      doc_->showDemonstration();
      break;
    case Step::Events:
      bring(timeline_dock_);
      doc_->showDemonstration();
      if (!doc_->issues().empty()) timeline_->jumpToIssue(0);
      break;
    case Step::Poses:
      bring(inspector_dock_);
      doc_->showDemonstration();
      if (doc_->selectedEvent() < 0 && !doc_->demonstration().events.empty()) doc_->selectEvent(0);
      break;
    case Step::Plan:
      bring(planner_dock_);
      break;
    case Step::Export:
      bring(result_dock_);
      if (doc_->planning()->interpolator()) doc_->setPlaybackT(doc_->playbackT());
      if (export_action_->isEnabled() && options_.interactive) showExportDialog();
      break;
  }
  statusBar()->showMessage(doc_->steps()->state(step).message, 8000);
}

// ----------------------------------------------------------------------------- files

bool MainWindow::maybeSave() {
  if (!doc_->isModified() || !options_.interactive) return true;
  const auto answer = QMessageBox::warning(this, tr("Unsaved changes"),
                                           tr("%1 has unsaved changes. Save them?").arg(doc_->displayName()),
                                           QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
  if (answer == QMessageBox::Cancel) return false;
  if (answer == QMessageBox::Save) return save();
  return true;
}

bool MainWindow::openProject(const QString& file) {
  QApplication::setOverrideCursor(Qt::WaitCursor);
  transport_->pause();
  try {
    removeAutosave();
    doc_->open(file);
  } catch (const std::exception& e) {
    QApplication::restoreOverrideCursor();
    reportError(tr("Cannot open the project"),
                tr("%1\n\nThe project was not opened. Check the file and the field named above, or open another "
                   "project (File > Open, or the sample).")
                    .arg(QString::fromUtf8(e.what())));
    return false;
  }
  QApplication::restoreOverrideCursor();
  addRecentFile(file);
  updateTitle();
  statusBar()->showMessage(tr("Opened %1").arg(QDir::toNativeSeparators(doc_->filePath())), 5000);
  if (!doc_->media()->videoError().isEmpty()) statusBar()->showMessage(doc_->media()->videoError(), 10000);
  return true;
}

bool MainWindow::openSample() {
  if (options_.sample_project.isEmpty() || !QFileInfo::exists(options_.sample_project)) {
    reportError(tr("No sample"), tr("The bundled sample project was not found (looked for %1). Reinstall demoplan, or "
                                    "start from a benchmark task: File > New from Benchmark Task.")
                                     .arg(options_.sample_project));
    return false;
  }
  if (!replaceProject(tr("Cannot open the sample"), [this] {
        doc_->open(options_.sample_project);
        doc_->setTemplate(true);
      }))
    return false;
  updateStatus();
  statusBar()->showMessage(tr("The sample project: a person moves two parts on a shelf, for a Panda. Scrub the "
                              "video, check the events and poses, press Plan (F5)."),
                           15000);
  return true;
}

bool MainWindow::replaceProject(const QString& failure_title, const std::function<void()>& make) {
  QApplication::setOverrideCursor(Qt::WaitCursor);
  try {
    removeAutosave();
    make();
  } catch (const std::exception& e) {
    QApplication::restoreOverrideCursor();
    reportError(failure_title, QString::fromUtf8(e.what()));
    return false;
  }
  QApplication::restoreOverrideCursor();
  updateTitle();
  return true;
}

bool MainWindow::newFromBenchmark(const QString& task, const QString& robot, int pose) {
  std::vector<std::string> deck_notes;
  if (!replaceProject(tr("Cannot create the project"),
                      [&] { deck_notes = doc_->newFromBenchmark(task.toStdString(), robot.toStdString(), pose); }))
    return false;
  // Objects riding on the robot's deck may have been moved from where the demonstrator put
  // them so the arm can pick them: say so, since the 3D view shows them there.
  if (!deck_notes.empty()) {
    QStringList lines;
    for (const auto& n : deck_notes) lines << QString::fromStdString(n);
    statusBar()->showMessage(tr("On the robot's deck: %1").arg(lines.join(QStringLiteral("; "))), 30000);
  }
  return true;
}

bool MainWindow::newFromCell(const QString& cell_file) {
  if (!replaceProject(tr("Cannot create the project"), [&] { doc_->newFromCell(cell_file.toStdString()); }))
    return false;
  statusBar()->showMessage(tr("A new project on %1: grasps were generated for its parts. Open the demonstration video "
                              "and extract its events (step 1).")
                               .arg(QFileInfo(cell_file).fileName()),
                           15000);
  return true;
}

void MainWindow::newCellDialog() {
  if (!maybeSave()) return;
  QStringList robots;
  for (const auto& r : list_benchmark_robots(options_.data_dir)) robots << QString::fromStdString(r);
  bool ok = false;
  const QString robot = QInputDialog::getItem(this, tr("New cell"), tr("The robot of the cell"), robots,
                                              std::max(0, static_cast<int>(robots.indexOf(QStringLiteral("ur5")))), false, &ok);
  if (!ok) return;
  QSettings settings;
  const QString file = QFileDialog::getSaveFileName(this, tr("Save the new cell as"),
                                                    settings.value("lastDir").toString() + QStringLiteral("/my_cell.json"),
                                                    tr("Cell files (*.json)"));
  if (file.isEmpty()) return;
  newCell(file, robot);
}

bool MainWindow::newCell(const QString& cell_file, const QString& robot) {
  try {
    save_cell(cell_file.toStdString(), starter_cell(cell_file.toStdString(), robot.toStdString(), options_.data_dir));
  } catch (const InputError& e) {
    reportError(tr("Cannot create the cell"), QString::fromStdString(e.what()));
    return false;
  }
  if (!newFromCell(cell_file)) return false;
  cell_dock_->show();
  cell_dock_->raise();
  statusBar()->showMessage(tr("A new cell: %1 at the origin and a table. Add parts from their mesh files in the Cell "
                              "panel; place everything by typing millimetres and degrees.")
                               .arg(robot),
                           20000);
  return true;
}

void MainWindow::newFromBenchmarkDialog() {
  if (!maybeSave()) return;
  QDialog dialog(this);
  dialog.setWindowTitle(tr("New project from a benchmark task"));
  auto* form = new QFormLayout(&dialog);
  auto* task = new QComboBox(&dialog);
  auto* robot = new QComboBox(&dialog);
  auto* pose = new QSpinBox(&dialog);
  try {
    for (const auto& t : list_benchmark_tasks(options_.data_dir)) task->addItem(QString::fromStdString(t));
    for (const auto& r : list_benchmark_robots(options_.data_dir)) robot->addItem(QString::fromStdString(r));
  } catch (const std::exception& e) {
    reportError(tr("Benchmark data"), QString::fromUtf8(e.what()));
    return;
  }
  task->setCurrentText(QStringLiteral("shelf_1"));
  robot->setCurrentText(QStringLiteral("panda"));
  pose->setRange(0, 99);
  pose->setToolTip(tr("The robot's base pose id in the task"));
  form->addRow(tr("Task"), task);
  form->addRow(tr("Robot"), robot);
  form->addRow(tr("Robot pose"), pose);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &dialog);
  form->addRow(buttons);
  connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
  if (dialog.exec() != QDialog::Accepted) return;
  newFromBenchmark(task->currentText(), robot->currentText(), pose->value());
}

bool MainWindow::save() {
  if (!doc_->hasProject()) return false;
  if (doc_->filePath().isEmpty() || doc_->isTemplate()) return saveAs();
  try {
    doc_->save();
  } catch (const std::exception& e) {
    reportError(tr("Cannot save"), tr("%1\n\nYour work is still open. Save it elsewhere (File > Save As).")
                                       .arg(QString::fromUtf8(e.what())));
    return false;
  }
  removeAutosave();
  addRecentFile(doc_->filePath());
  statusBar()->showMessage(tr("Saved %1").arg(QDir::toNativeSeparators(doc_->filePath())), 5000);
  return true;
}

bool MainWindow::saveAs(const QString& file_in) {
  if (!doc_->hasProject()) return false;
  QString file = file_in;
  if (file.isEmpty()) {
    if (!options_.interactive) return false;
    QSettings settings;
    QString suggestion = settings.value(QStringLiteral("lastDir"), QDir::homePath()).toString() + QLatin1Char('/') +
                         QString::fromStdString(doc_->sceneReference().is_cell()
                                                    ? std::filesystem::path(doc_->sceneReference().cell).stem().string()
                                                    : doc_->sceneReference().task) +
                         QStringLiteral(".demoplan");
    file = QFileDialog::getSaveFileName(this, tr("Save project as"), suggestion, tr(kProjectFilter));
    if (file.isEmpty()) return false;
  }
  if (QFileInfo(file).suffix().isEmpty()) file += QStringLiteral(".demoplan");
  const QString old_autosave = autosavePath();
  try {
    doc_->saveAs(file);
  } catch (const std::exception& e) {
    reportError(tr("Cannot save"), tr("%1\n\nYour work is still open. Choose another folder.").arg(QString::fromUtf8(e.what())));
    return false;
  }
  QFile::remove(old_autosave);
  QFile::remove(old_autosave + QStringLiteral(".origin"));
  removeAutosave();
  addRecentFile(file);
  updateTitle();
  statusBar()->showMessage(tr("Saved %1").arg(QDir::toNativeSeparators(doc_->filePath())), 5000);
  return true;
}

bool MainWindow::openVideo(const QString& file_in) {
  if (!doc_->hasProject()) {
    reportError(tr("Open video"), tr("Open or create a project first: the video belongs to a project."));
    return false;
  }
  QString file = file_in;
  if (file.isEmpty()) {
    if (!options_.interactive) return false;
    file = QFileDialog::getOpenFileName(this, tr("Open video"), QFileInfo(doc_->filePath()).absolutePath(),
                                        tr("Videos (*.mp4 *.avi *.mkv *.mov *.m4v *.webm);;All files (*)"));
    if (file.isEmpty()) return false;
  }
  doc_->setMediaFile(Media::File::Video, file);
  if (!doc_->media()->videoError().isEmpty()) {
    reportError(tr("Cannot open the video"),
                doc_->media()->videoError() + tr("\n\nCheck that the file is a complete video (mp4, avi, mkv) and try another."));
    return false;
  }
  statusBar()->showMessage(tr("Video %1: %2 frames").arg(QFileInfo(file).fileName()).arg(doc_->frameCount()), 5000);
  return true;
}

bool MainWindow::openCamera(const QString& file_in) {
  if (!doc_->hasProject()) return false;
  QString file = file_in;
  if (file.isEmpty()) {
    if (!options_.interactive) return false;
    file = QFileDialog::getOpenFileName(this, tr("Open camera calibration"), QFileInfo(doc_->filePath()).absolutePath(),
                                        tr("Camera files (*.json *.yaml *.yml *.xml);;All files (*)"));
    if (file.isEmpty()) return false;
  }
  doc_->setMediaFile(Media::File::Camera, file);
  if (!doc_->media()->cameraError().isEmpty()) {
    reportError(tr("Cannot read the camera calibration"), doc_->media()->cameraError());
    return false;
  }
  return true;
}

// ---------------------------------------------------------------------- autosave, start

QString MainWindow::autosavePath() const {
  const QString dir = QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + QStringLiteral("/autosave");
  const QString key = doc_->filePath().isEmpty() || doc_->isTemplate() ? QStringLiteral("untitled") : doc_->filePath();
  const QString hash = QString::fromLatin1(QCryptographicHash::hash(key.toUtf8(), QCryptographicHash::Sha1).toHex().left(12));
  return dir + QLatin1Char('/') + hash + QStringLiteral(".demoplan");
}

void MainWindow::autosaveNow() {
  if (!doc_->hasProject() || !doc_->isModified()) return;
  const QString path = autosavePath();
  QDir().mkpath(QFileInfo(path).absolutePath());
  try {
    doc_->saveCopy(path);
    QFile origin(path + QStringLiteral(".origin"));
    if (origin.open(QIODevice::WriteOnly | QIODevice::Truncate)) {
      origin.write((doc_->isTemplate() ? QString() : doc_->filePath()).toUtf8());
    }
    statusBar()->showMessage(tr("Autosaved"), 2000);
  } catch (const std::exception& e) {
    statusBar()->showMessage(tr("Autosave failed: %1").arg(QString::fromUtf8(e.what())), 10000);
  }
}

void MainWindow::removeAutosave() {
  if (!doc_->hasProject()) return;
  const QString path = autosavePath();
  QFile::remove(path);
  QFile::remove(path + QStringLiteral(".origin"));
  QFile::remove(QFileInfo(path).absolutePath() + QLatin1Char('/') + QFileInfo(path).completeBaseName() +
                QStringLiteral(".path.json"));
}

std::optional<MainWindow::Autosave> MainWindow::pendingAutosave() const {
  const QDir dir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + QStringLiteral("/autosave"));
  const QFileInfoList files = dir.entryInfoList({QStringLiteral("*.demoplan")}, QDir::Files, QDir::Time);
  if (files.isEmpty()) return std::nullopt;
  Autosave a;
  a.file = files.front().absoluteFilePath();
  a.time = files.front().lastModified();
  QFile origin(a.file + QStringLiteral(".origin"));
  if (origin.open(QIODevice::ReadOnly)) a.origin = QString::fromUtf8(origin.readAll());
  return a;
}

bool MainWindow::recoverAutosave(const Autosave& a) {
  try {
    doc_->open(a.file);
    if (!a.origin.isEmpty()) doc_->setFilePath(a.origin);
    else doc_->setTemplate(true);
    doc_->setModified();
  } catch (const std::exception& e) {
    reportError(tr("Cannot recover"), tr("%1\n\nThe autosave is kept in %2.").arg(QString::fromUtf8(e.what()), a.file));
    return false;
  }
  QFile::remove(a.file);
  QFile::remove(a.file + QStringLiteral(".origin"));
  updateTitle();
  statusBar()->showMessage(tr("Recovered the autosaved work: save it to keep it"), 10000);
  return true;
}

void MainWindow::discardAutosaves() {
  const QDir dir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + QStringLiteral("/autosave"));
  for (const QFileInfo& f : dir.entryInfoList(QDir::Files)) QFile::remove(f.absoluteFilePath());
}

bool MainWindow::offerRecovery(const QString& only_for) {
  const std::optional<Autosave> a = pendingAutosave();
  if (!a || !options_.interactive) return false;
  // Opening a given project: only its own autosave is offered, the others stay for later.
  if (!only_for.isEmpty() && a->origin != QFileInfo(only_for).absoluteFilePath()) return false;
  QMessageBox box(QMessageBox::Question, tr("Recover unsaved work?"),
                  tr("demoplan did not close properly last time. Unsaved changes to %1 were autosaved %2.")
                      .arg(a->origin.isEmpty() ? tr("an untitled project") : QFileInfo(a->origin).fileName(),
                           a->time.toString(Qt::TextDate)),
                  QMessageBox::NoButton, this);
  QPushButton* recover = box.addButton(tr("Recover"), QMessageBox::AcceptRole);
  box.addButton(tr("Discard"), QMessageBox::DestructiveRole);
  box.exec();
  if (box.clickedButton() != recover) {
    discardAutosaves();
    return false;
  }
  return recoverAutosave(*a);
}

void MainWindow::startUp(const QString& file) {
  QSettings settings;
  if (!file.isEmpty()) {
    // After a crash the project's autosave is newer than the file: offer it first.
    if (offerRecovery(file)) return;
    openProject(file);
    settings.setValue(QStringLiteral("firstStartDone"), true);
    return;
  }
  if (offerRecovery()) return;
  if (!settings.value(QStringLiteral("firstStartDone"), false).toBool()) {
    settings.setValue(QStringLiteral("firstStartDone"), true);
    openSample();
    return;
  }
  for (const QString& f : recentFiles())
    if (QFileInfo::exists(f)) {
      if (openProject(f)) return;
      break;
    }
  openSample();
}

void MainWindow::closeEvent(QCloseEvent* e) {
  if (!maybeSave()) {
    e->ignore();
    return;
  }
  if (doc_->planning()->runner()->isRunning()) doc_->planning()->runner()->cancel();
  QSettings settings;
  settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
  settings.setValue(QStringLiteral("window/state"), saveState());
  removeAutosave();
  e->accept();
}

void MainWindow::dragEnterEvent(QDragEnterEvent* e) {
  if (!e->mimeData()->hasUrls()) return;
  for (const QUrl& u : e->mimeData()->urls()) {
    const QString f = u.toLocalFile();
    if (f.endsWith(QStringLiteral(".demoplan")) || isVideoFile(f)) {
      e->acceptProposedAction();
      return;
    }
  }
}

void MainWindow::dropEvent(QDropEvent* e) {
  for (const QUrl& u : e->mimeData()->urls()) {
    const QString f = u.toLocalFile();
    if (f.endsWith(QStringLiteral(".demoplan"))) {
      if (maybeSave()) openProject(f);
      e->acceptProposedAction();
      return;
    }
    if (isVideoFile(f)) {
      openVideo(f);
      e->acceptProposedAction();
      return;
    }
  }
}

// ------------------------------------------------------------------------------- misc

ExportDialog* MainWindow::showExportDialog() {
  if (!doc_->planning()->result() || !doc_->planning()->result()->path) {
    reportError(tr("Export"), tr("There is no planned path to export yet: press Plan (F5) first."));
    return nullptr;
  }
  auto* dialog = new ExportDialog(doc_, options_.interactive, this);
  dialog->setAttribute(Qt::WA_DeleteOnClose);
  connect(dialog, &QDialog::accepted, this, [this] {
    statusBar()->showMessage(doc_->steps()->state(Step::Export).message, 8000);
  });
  if (options_.interactive) dialog->open();
  else dialog->show();
  return dialog;
}

bool MainWindow::detectEventsFromTracks() {
  int events = 0;
  QApplication::setOverrideCursor(Qt::WaitCursor);  // a fraction of a second on the GUI thread
  try {
    events = doc_->trackDetection()->detect();
  } catch (const std::exception& e) {
    QApplication::restoreOverrideCursor();
    reportError(tr("Detect events from tracks"),
                tr("%1\n\nThe events are unchanged.").arg(QString::fromUtf8(e.what())));
    return false;
  }
  QApplication::restoreOverrideCursor();
  if (!tracks_dock_->isVisible()) {
    tracks_dock_->show();
    // Room for the curves, once the dock is laid out; the timeline keeps its lanes.
    QTimer::singleShot(0, this, [this] {
      resizeDocks({timeline_dock_, tracks_dock_}, {timeline_dock_->height(), 260}, Qt::Vertical);
    });
  }
  tracks_dock_->raise();
  const size_t doubts = doc_->demonstration().doubts.size();
  QString text = tr("Found %1 events from the tracks").arg(events);
  if (doubts > 0) text += tr("; %1 doubt(s) hatched on the timeline (Ctrl+Shift+J)").arg(doubts);
  statusBar()->showMessage(text + tr(". Ctrl+Z brings the previous events back."), 15000);
  return true;
}

void MainWindow::addEventAtPlayhead(EventType type) {
  if (!doc_->hasProject()) return;
  int object = doc_->selectedObject();
  if (object < 0) {
    statusBar()->showMessage(tr("Select a part first (click it in the 3D view or its lane in the timeline)"), 5000);
    return;
  }
  doc_->selectEvent(doc_->addEvent(doc_->currentFrame(), object, type));
}

void MainWindow::placePartAgain() {
  const int object = doc_->hasProject() ? doc_->selectedObject() : -1;
  if (object < 0) {
    statusBar()->showMessage(tr("Select a part first (click it in the 3D view or its lane in the timeline)"), 5000);
    return;
  }
  if (doc_->currentFrame() < 1) {
    statusBar()->showMessage(tr("Frame 0 is the start: move the part itself there"), 5000);
    return;
  }
  doc_->placeAgain(object);
  const QString id = QString::fromStdString(doc_->demonstration().object_ids[size_t(object)]);
  QString text = tr("%1 placed again at frame %2: move it (3D view or Inspector) until its outline lies on it in the "
                    "video, then Detect Events (Ctrl+D)")
                     .arg(id)
                     .arg(doc_->currentFrame());
  if (!doc_->detection()->modelTracker()) text += tr("; only the Part models tracker uses it");
  statusBar()->showMessage(text, 15000);
}

void MainWindow::placeStartsFromEstimates() {
  if (!doc_->hasProject()) return;
  const QString file = QFileDialog::getOpenFileName(this, tr("Pose estimates of the start frame"),
                                                    QFileInfo(doc_->filePath()).absolutePath(),
                                                    tr("BOP results (*.csv);;All files (*)"));
  if (file.isEmpty()) return;
  try {
    const int placed = doc_->placeStartsFromEstimates(file.toStdString());
    doc_->setCurrentFrame(0);
    statusBar()->showMessage(tr("%n part(s) placed where %1 shows them in frame 0: check each outline over the video, "
                                "then Detect Events (Ctrl+D)",
                                nullptr, placed)
                                 .arg(QFileInfo(file).fileName()),
                             15000);
  } catch (const std::exception& e) {
    reportError(tr("Place parts from pose estimates"), QString::fromStdString(e.what()));
  }
}

void MainWindow::showShortcuts() {
  const QString rows[][2] = {{"Space", tr("play / pause (the video, or the path when it is shown)")},
                             {"← / →", tr("one frame back / forward")},
                             {"Shift+← / →", tr("one second back / forward")},
                             {"J / K / L", tr("play backward / pause / play forward (again: faster)")},
                             {"Home / End", tr("first / last frame")},
                             {"G / R", tr("add a grasp / release of the selected part at the playhead")},
                             {"Del", tr("delete the selected event")},
                             {"Ctrl+Z / Ctrl+Shift+Z", tr("undo / redo")},
                             {"Ctrl+J", tr("go to the event that breaks a rule")},
                             {"Ctrl+Shift+J", tr("go to the next detection doubt")},
                             {"Ctrl+Shift+D", tr("detect the events from the benchmark task's pose tracks")},
                             {"Ctrl+Shift+P", tr("place the selected part again over this frame (part models)")},
                             {"F", tr("fit the 3D view")},
                             {"T", tr("show / hide the planner's trees")},
                             {"F5 / Esc", tr("plan / cancel planning")},
                             {"Ctrl+S / Ctrl+Shift+S", tr("save / save as")},
                             {tr("3D view"), tr("left-drag orbit · right/middle-drag pan · wheel zoom · click selects a part · "
                                                "drag the gizmo's arrows or ring to move it (Ctrl: coarse steps)")},
                             {tr("Timeline"), tr("click/drag the playhead · drag a marker to move the event · double-click "
                                                 "a lane to add one · right-click for more")}};
  QString html = QStringLiteral("<table cellspacing=4>");
  for (const auto& r : rows) html += QStringLiteral("<tr><td><b>%1</b></td><td>%2</td></tr>").arg(r[0], r[1]);
  html += QStringLiteral("</table>");
  QMessageBox::information(this, tr("Keyboard shortcuts"), html);
}

void MainWindow::showAbout() {
  QMessageBox::about(this, tr("About demoplan"),
                     tr("<b>demoplan</b> %1<br>Teach a robot cell a pick-and-place task from one video: review the "
                        "detected grasps and releases, correct the parts' poses, plan with the video-guided "
                        "multi-contact RRT (Zorina et al., ICRA 2023) and export the program.<br><br>3D view: %2")
                         .arg(QCoreApplication::applicationVersion(), scene_view_->glInfo()));
}

}  // namespace demoplan::ui
