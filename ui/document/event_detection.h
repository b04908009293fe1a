#pragma once
// The Events step's automatic part: detecting the grasps and releases in the project's video
// (ExtractionRunner on a background thread). A result replaces the demonstration as one
// undoable edit.
#include <QObject>
#include <QString>

#include "perception/tracking/tracker_init.h"
#include "ui/document/extraction_runner.h"

namespace demoplan::ui {

class Document;

class EventDetection : public QObject {
  Q_OBJECT
public:
  explicit EventDetection(Document* doc);

  ExtractionRunner* runner() { return &runner_; }
  bool isRunning() const { return runner_.isRunning(); }
  // What is missing to detect events; empty when start() can run.
  QString blocker() const;
  bool start();

  // Markers on the parts, or the parts' models: then every part starts from init.json beside
  // the marker scene when there is one, else from where the project shows it at frame 0 (the
  // operator places it there). Chosen anew whenever a marker scene is opened: the models when
  // no part in it carries a marker, else the markers.
  void setModelTracker(bool model);
  bool modelTracker() const { return model_tracker_; }
  // Where the part models start as start() would give them to the tracker (the rule above), with
  // the parts placed again (init.json's corrections, then the project's: Document::corrections),
  // for the run and for the video panel's outlines; `source` names it. Throws InputError when
  // init.json cannot be read or a part placed again has no start or is placed before it.
  perception::TrackerInit modelTrackerStart(std::string* source = nullptr) const;
  // The source modelTrackerStart() names when the parts start where the project shows them.
  static constexpr const char* kPosesAtFrameZero = "the parts' poses at frame 0";

signals:
  void trackerChanged(bool model);
  // After the demonstration was replaced (ok) or nothing was (not ok: the error says why).
  void done(const ExtractionOutcome& outcome);

private:
  void onFinished(const ExtractionOutcome& outcome);
  void chooseTracker();  // for the marker scene just opened

  Document* doc_;
  ExtractionRunner runner_;
  bool model_tracker_ = false;
};

}  // namespace demoplan::ui
