#pragma once
// The main window (UX.md): the step bar, the 3D scene in the middle, dockable panels (video,
// timeline, inspector, planner, result, history) whose layout is restored on the next start,
// menus, a toolbar, a status bar, recent files, keyboard shortcuts, autosave with recovery after
// a crash, drag-and-drop of projects and videos.
#include <QDateTime>
#include <QMainWindow>
#include <QPointer>
#include <functional>
#include <optional>

#include "ui/document/document.h"

class QDockWidget;
class QLabel;
class QMenu;
class QTimer;
class QUndoView;

class QDragEnterEvent;
class QDropEvent;

namespace demoplan::ui {

class CellPanel;
class ExportDialog;
class PartTracksPanel;
class PlacementPanel;
class PlannerPanel;
class PoseEditor;
class ResultPanel;
class SceneView;
class StepBar;
class TimelinePanel;
class Transport;
class VideoPanel;

struct MainWindowOptions {
  std::string data_dir;        // the benchmark data folder
  QString sample_project;      // opened on first start; empty: none
  bool interactive = true;     // modal dialogs; false (tests): errors go to lastError() and the status bar
  int autosave_interval_ms = 60'000;
  bool restore_layout = true;  // restore window geometry and docks from QSettings
};

class MainWindow : public QMainWindow {
  Q_OBJECT
public:
  explicit MainWindow(MainWindowOptions options, QWidget* parent = nullptr);
  ~MainWindow() override;

  Document* document() const { return doc_; }
  SceneView* sceneView() const { return scene_view_; }
  TimelinePanel* timelinePanel() const { return timeline_; }
  PartTracksPanel* partTracksPanel() const { return part_tracks_; }
  QDockWidget* partTracksDock() const { return tracks_dock_; }
  PoseEditor* poseEditor() const { return pose_editor_; }
  PlannerPanel* plannerPanel() const { return planner_; }
  PlacementPanel* placementPanel() const { return placement_; }
  QDockWidget* placementDock() const { return placement_dock_; }
  ResultPanel* resultPanel() const { return result_; }
  VideoPanel* videoPanel() const { return video_; }
  StepBar* stepBar() const { return step_bar_; }
  Transport* transport() const { return transport_; }
  QString lastError() const { return last_error_; }
  QStringList recentFiles() const;
  // The autosave file of the current project (it may not exist yet).
  QString autosavePath() const;

  // What the menu items do; each returns false (and reports why) when it did not happen.
  bool openProject(const QString& file);
  bool openSample();
  bool newFromBenchmark(const QString& task, const QString& robot, int pose);
  bool newFromCell(const QString& cell_file);
  // A starter cell (starter_cell) with `robot`, written to `cell_file`, and a project on it.
  bool newCell(const QString& cell_file, const QString& robot);
  CellPanel* cellPanel() const { return cell_panel_; }
  QDockWidget* cellDock() const { return cell_dock_; }
  bool save();
  bool saveAs(const QString& file = QString());
  bool openVideo(const QString& file = QString());
  bool openCamera(const QString& file = QString());
  // Edit > Detect Events from Tracks: replaces the events (one undo step), shows the Part Tracks.
  bool detectEventsFromTracks();
  // Startup: a file from the command line, else recovery of a crashed session, else the most
  // recent project, else the sample.
  void startUp(const QString& file_from_command_line);
  void autosaveNow();
  // A project autosaved by a session that did not end cleanly (the newest), if any.
  struct Autosave {
    QString file;    // the autosave
    QString origin;  // the project it belongs to; empty for an untitled project or the sample
    QDateTime time;
  };
  std::optional<Autosave> pendingAutosave() const;
  // Opens it; Save then writes to its origin (or asks, without one).
  bool recoverAutosave(const Autosave& autosave);
  void discardAutosaves();
  void showStep(Step step);
  // Opens the export dialog (modeless without interaction, for tests); null when nothing to export.
  ExportDialog* showExportDialog();

protected:
  void closeEvent(QCloseEvent*) override;
  void dragEnterEvent(QDragEnterEvent*) override;
  void dropEvent(QDropEvent*) override;

private:
  void createActions();
  void createDocks();
  void updateTitle();
  void updateSteps();
  void updateStatus();
  void updateRecentMenu();
  void addRecentFile(const QString& file);
  void reportError(const QString& title, const QString& message);
  bool maybeSave();
  void newFromBenchmarkDialog();
  void newCellDialog();
  void removeAutosave();
  // Replaces the open project by what `make` loads into the document (the old project's
  // autosave dropped first, a wait cursor meanwhile); a failure is reported under
  // `failure_title`, the old project stays open.
  bool replaceProject(const QString& failure_title, const std::function<void()>& make);
  bool offerRecovery(const QString& only_for = {});  // only_for: a project file; empty: any
  void showShortcuts();
  void showAbout();
  void addEventAtPlayhead(EventType type);
  void placePartAgain();  // the selected part at the playhead (Document::placeAgain)
  // Every part at its start where a pose estimator's BOP CSV shows it in frame 0 (asks for the file).
  void placeStartsFromEstimates();
  QDockWidget* addDock(const QString& title, const QString& name, QWidget* widget, Qt::DockWidgetArea area);

  MainWindowOptions options_;
  Document* doc_;
  Transport* transport_;
  SceneView* scene_view_ = nullptr;
  VideoPanel* video_ = nullptr;
  TimelinePanel* timeline_ = nullptr;
  PartTracksPanel* part_tracks_ = nullptr;
  PoseEditor* pose_editor_ = nullptr;
  CellPanel* cell_panel_ = nullptr;
  PlannerPanel* planner_ = nullptr;
  PlacementPanel* placement_ = nullptr;
  ResultPanel* result_ = nullptr;
  QUndoView* history_ = nullptr;
  StepBar* step_bar_ = nullptr;
  QDockWidget *video_dock_ = nullptr, *timeline_dock_ = nullptr, *inspector_dock_ = nullptr, *planner_dock_ = nullptr,
              *result_dock_ = nullptr, *history_dock_ = nullptr, *placement_dock_ = nullptr,
              *tracks_dock_ = nullptr, *cell_dock_ = nullptr;
  QMenu* recent_menu_ = nullptr;
  QMenu* view_menu_ = nullptr;
  QLabel* frame_label_ = nullptr;
  QLabel* saved_label_ = nullptr;
  QTimer* autosave_timer_ = nullptr;
  QTimer* status_timer_ = nullptr;
  qint64 saved_at_ms_ = 0;
  QString last_error_;
  QByteArray default_state_;
  QAction *save_action_ = nullptr, *plan_action_ = nullptr, *cancel_action_ = nullptr, *export_action_ = nullptr,
          *delete_action_ = nullptr, *track_detect_action_ = nullptr;
};

}  // namespace demoplan::ui
