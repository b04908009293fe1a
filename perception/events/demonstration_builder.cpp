#include "perception/events/demonstration_builder.h"

#include <algorithm>
#include <cmath>

#include "core/demo/rest_pose.h"

namespace demoplan::perception {

std::optional<std::pair<int, int>> rest_interval(const std::vector<MotionInterval>& motions, int frame, int frames) {
  int first = 0, last = frames - 1;
  for (const auto& m : motions) {
    if (m.start < frame && frame < m.end) return std::nullopt;
    if (m.end <= frame) first = std::max(first, m.end);
    if (m.start >= frame) last = std::min(last, m.start);
  }
  return std::make_pair(first, last);
}

std::optional<Pose> rest_pose(const std::vector<PoseSample>& samples, int first, int last,
                              const ContactDetectorOptions& options) {
  const std::vector<bool> usable = usable_samples(samples, options);
  PoseList poses, weak;
  for (int f = std::max(0, first); f <= last && f < static_cast<int>(samples.size()); ++f)
    if (samples[f].valid) (usable[f] ? poses : weak).push_back(samples[f].pose);
  if (poses.empty()) poses = weak;
  if (poses.empty()) return std::nullopt;
  return robust_static_pose(poses);
}

namespace {

// The sample nearest in time to `frame`, if any.
std::optional<Pose> nearest_sample(const std::vector<PoseSample>& samples, int frame) {
  const int n = static_cast<int>(samples.size());
  for (int d = 0; d < n; ++d)
    for (int f : {frame - d, frame + d})
      if (f >= 0 && f < n && samples[f].valid) return samples[f].pose;
  return std::nullopt;
}

}  // namespace

Demonstration build_demonstration(const PoseTracks& tracks, const ContactAnalysis& contacts, const std::string& task,
                                  const ContactDetectorOptions& options, std::vector<std::string>* warnings) {
  Demonstration d;
  d.task = task;
  d.fps = tracks.fps;
  std::vector<int> rows;  // track row of each planning object
  for (size_t k = 0; k < tracks.object_ids.size(); ++k)
    if (tracks.planning[k]) {
      d.object_ids.push_back(tracks.object_ids[k]);
      rows.push_back(static_cast<int>(k));
    }
  auto planning_index = [&](int row) {
    return static_cast<int>(std::find(rows.begin(), rows.end(), row) - rows.begin());
  };
  for (const auto& c : contacts.carries) {
    if (!c.seen_at_rest_after && warnings)
      warnings->push_back(tracks.object_ids[c.object] + " at frames " + std::to_string(c.start) + "-" + std::to_string(c.end) +
                          ": carried and never seen at rest after (hidden or still moving when the video ends); its "
                          "release is put where it was last seen, frame " + std::to_string(c.end) +
                          ": check that pose before planning");
    d.events.push_back({c.start, planning_index(c.object), EventType::Grasp, std::clamp(c.start_confidence, 0.0, 1.0), {}, {}});
    d.events.push_back({c.end, planning_index(c.object), EventType::Release, std::clamp(c.end_confidence, 0.0, 1.0), {}, {}});
  }
  // By frame; a release before a grasp at the same frame (the hand lets go, then takes the next).
  std::stable_sort(d.events.begin(), d.events.end(), [](const ContactEvent& a, const ContactEvent& b) {
    if (a.frame != b.frame) return a.frame < b.frame;
    return a.type == EventType::Release && b.type == EventType::Grasp;
  });
  std::vector<std::vector<MotionInterval>> motions(tracks.object_ids.size());
  for (size_t k = 0; k < motions.size(); ++k) motions[k] = contacts.motions_of(static_cast<int>(k));
  for (auto& e : d.events)
    for (size_t p = 0; p < rows.size(); ++p) {
      const int row = rows[p];
      std::optional<Pose> pose;
      if (const auto rest = rest_interval(motions[row], e.frame, tracks.frames))
        pose = rest_pose(tracks.samples[row], rest->first, rest->second, options);
      if (!pose) {
        pose = nearest_sample(tracks.samples[row], e.frame);
        if (warnings)
          warnings->push_back(d.object_ids[p] + " at frame " + std::to_string(e.frame) + ": " +
                              (pose ? "not seen at rest, nearest sample used" : "never seen, identity pose used"));
      }
      e.poses.push_back(pose.value_or(Pose::Identity()));
    }
  return d;
}

}  // namespace demoplan::perception
