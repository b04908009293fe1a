#include "perception/events/evaluation.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <tuple>

#include "core/statistics.h"

namespace demoplan::perception {

namespace {

const std::string& id_of(const Demonstration& d, const ContactEvent& e) { return d.object_ids.at(e.object); }

}  // namespace

DemonstrationEvaluation evaluate_demonstration(const Demonstration& detected, const Demonstration& truth,
                                               int tolerance, const std::map<std::string, std::vector<Eigen::Vector3d>>& models) {
  DemonstrationEvaluation r;
  r.truth_events = static_cast<int>(truth.events.size());
  r.detected_events = static_cast<int>(detected.events.size());
  std::vector<std::tuple<int, int, int>> pairs;  // |error|, truth, detected
  for (int t = 0; t < r.truth_events; ++t)
    for (int d = 0; d < r.detected_events; ++d) {
      const auto& et = truth.events[t];
      const auto& ed = detected.events[d];
      if (et.type != ed.type || id_of(truth, et) != id_of(detected, ed)) continue;
      const int err = std::abs(ed.frame - et.frame);
      if (err <= tolerance) pairs.emplace_back(err, t, d);
    }
  std::sort(pairs.begin(), pairs.end());
  std::vector<bool> used_t(r.truth_events, false), used_d(r.detected_events, false);
  for (const auto& [err, t, d] : pairs) {
    if (used_t[t] || used_d[d]) continue;
    used_t[t] = used_d[d] = true;
    r.matches.push_back({t, d, detected.events[d].frame - truth.events[t].frame});
  }
  std::sort(r.matches.begin(), r.matches.end(), [](auto& a, auto& b) { return a.truth < b.truth; });
  r.matched = static_cast<int>(r.matches.size());
  r.precision = r.detected_events ? double(r.matched) / r.detected_events : (r.truth_events ? 0.0 : 1.0);
  r.recall = r.truth_events ? double(r.matched) / r.truth_events : 1.0;
  std::vector<double> timing, trans, rot, mssd;
  for (const auto& m : r.matches) {
    timing.push_back(std::abs(m.timing_error));
    const auto& et = truth.events[m.truth];
    const auto& ed = detected.events[m.detected];
    for (size_t o = 0; o < truth.object_ids.size() && o < et.poses.size(); ++o) {
      const int k = detected.object_index(truth.object_ids[o]);
      if (k < 0 || k >= static_cast<int>(ed.poses.size())) continue;
      if (!et.pose_frame(static_cast<int>(o)).empty() || !ed.pose_frame(k).empty()) continue;  // not in the world
      const Pose& pt = et.poses[o];
      const Pose& pd = ed.poses[k];
      trans.push_back((pt.translation() - pd.translation()).norm() * 1000.0);
      rot.push_back(Eigen::AngleAxisd(pt.linear().transpose() * pd.linear()).angle() * 180.0 / M_PI);
      if (const auto it = models.find(truth.object_ids[o]); it != models.end() && !it->second.empty()) {
        double worst = 0;
        for (const auto& x : it->second) worst = std::max(worst, (pd * x - pt * x).norm());
        mssd.push_back(worst * 1000.0);
      }
    }
  }
  r.median_timing_error_frames = median(timing);
  r.pose_pairs = static_cast<int>(trans.size());
  r.median_translation_error_mm = median(trans);
  r.median_rotation_error_deg = median(rot);
  r.max_translation_error_mm = trans.empty() ? 0.0 : *std::max_element(trans.begin(), trans.end());
  r.max_rotation_error_deg = rot.empty() ? 0.0 : *std::max_element(rot.begin(), rot.end());
  if (!mssd.empty()) r.median_mssd_mm = median(mssd);
  r.timing_errors = timing;
  r.translation_errors_mm = trans;
  r.rotation_errors_deg = rot;
  r.mssd_errors_mm = mssd;
  return r;
}

}  // namespace demoplan::perception
