#pragma once
// The placement search of the open project (core/placement) on a background thread: where could
// the robot stand for this demonstration, and how long would the cycle take there? Candidates
// arrive one by one (the heat map fills in as they come), cancel answers at once, and the last
// search's results stay until the next one or another project. The region defaults to 1.2 m
// around the robot's base and every yaw.
#include <vector>

#include "core/placement/base_placement.h"
#include "ui/document/background_job.h"

namespace demoplan::ui {

class Document;

struct PlacementSearchSettings {
  PlacementRegion region;
  int samples = 60;
  int seeds = 3;              // seeds 1..seeds per candidate
  double time_limit_s = 10;   // per planning run
  int jobs = 2;               // candidates at once
};

class PlacementSearchJob : public BackgroundJob {
  Q_OBJECT
public:
  explicit PlacementSearchJob(Document* doc);

  // The settings of the next search (the region around the robot until the operator sets one).
  PlacementSearchSettings settings() const;
  void setSettings(const PlacementSearchSettings& settings);
  // Starts a search of the project's scene and demonstration; false, with `error`, when one runs,
  // the demonstration has issues or the robot is mobile.
  bool start(QString* error = nullptr);

  const std::vector<PlacementCandidate>& candidates() const { return candidates_; }  // in arrival order
  int total() const { return total_; }  // of the running or last search
  // The best candidate with a valid plan (rank_candidates' first), or nullptr.
  const PlacementCandidate* best() const;
  void clear();

signals:
  void candidateDone(int done, int total);
  void finished();
  void cleared();

private:
  Document* doc_;
  std::optional<PlacementSearchSettings> settings_;
  std::vector<PlacementCandidate> candidates_;
  int total_ = 0;
};

}  // namespace demoplan::ui
