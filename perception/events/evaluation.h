#pragma once
// How well an extracted demonstration matches the ground truth: events matched one to one
// (same part, same type, within a frame tolerance, closest first), precision, recall, timing
// error, and the errors of the part poses at the matched events.
#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/demo/demonstration.h"

namespace demoplan::perception {

struct EventMatch {
  int truth = -1, detected = -1;  // event indices
  int timing_error = 0;           // detected frame - truth frame
};

struct DemonstrationEvaluation {
  int truth_events = 0, detected_events = 0, matched = 0;
  double precision = 0.0, recall = 0.0;
  double median_timing_error_frames = 0.0;  // |error|
  int pose_pairs = 0;                       // (matched event, part) pairs compared
  double median_translation_error_mm = 0.0, max_translation_error_mm = 0.0;
  double median_rotation_error_deg = 0.0, max_rotation_error_deg = 0.0;
  // BOP's maximum symmetry-aware surface distance with the identity as the only symmetry
  // (the largest displacement of a model point); -1 without models.
  double median_mssd_mm = -1.0;
  std::vector<EventMatch> matches;
  // The individual values the medians are taken over, for pooling several evaluations.
  std::vector<double> timing_errors, translation_errors_mm, rotation_errors_deg, mssd_errors_mm;
};

// `models`: part id -> points of its model in the part frame (metres), for the MSSD.
DemonstrationEvaluation evaluate_demonstration(const Demonstration& detected, const Demonstration& truth,
                                               int tolerance_frames = 2,
                                               const std::map<std::string, std::vector<Eigen::Vector3d>>& models = {});

}  // namespace demoplan::perception
