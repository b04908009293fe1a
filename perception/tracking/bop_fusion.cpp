#include "perception/tracking/bop_fusion.h"

#include <algorithm>
#include <map>
#include <set>

#include "core/error.h"

namespace demoplan::perception {

int fuse_bop_detections(PoseTracks& tracks, const std::vector<BopDetection>& detections, const Pose& world_T_camera,
                        const std::string& source, double weight, std::vector<std::string>* warnings) {
  std::map<int, int> row_of_model;
  for (size_t k = 0; k < tracks.object_ids.size(); ++k)
    if (const int id = bop_object_id(tracks.object_ids[k]); id >= 0) row_of_model[id] = static_cast<int>(k);
  // The best-scoring estimate per (part, frame).
  std::map<std::pair<int, int>, const BopDetection*> best;
  std::set<int> unknown;
  for (const auto& d : detections) {
    if (d.image_id >= tracks.frames)
      throw InputError(source, "line " + std::to_string(d.line),
                       "im_id " + std::to_string(d.image_id) + " is beyond the video's last frame " +
                           std::to_string(tracks.frames - 1));
    const auto it = row_of_model.find(d.object_id);
    if (it == row_of_model.end()) {
      unknown.insert(d.object_id);
      continue;
    }
    auto& slot = best[{it->second, d.image_id}];
    if (!slot || d.score > slot->score) slot = &d;
  }
  if (warnings)
    for (int id : unknown)
      warnings->push_back(source + ": obj_id " + std::to_string(id) + " is none of the scene's parts; its estimates are ignored");
  int added = 0;
  for (const auto& [key, d] : best) {
    PoseSample& s = tracks.samples[key.first][key.second];
    if (s.valid && s.markers > 0) continue;  // markers are more accurate
    s.valid = true;
    s.pose = world_T_camera * d->camera_T_object;
    s.confidence = std::clamp(d->score, 0.0, 1.0) * weight;
    s.markers = 0;
    s.reprojection_px = 0;
    ++added;
  }
  return added;
}

}  // namespace demoplan::perception
