#include "perception/tracking/tracker_init_bop.h"

#include <map>

#include "core/error.h"

namespace demoplan::perception {

TrackerInit tracker_init_from_bop(const std::vector<BopDetection>& detections, const std::vector<std::string>& parts,
                                  const Pose& world_T_camera, const std::string& source) {
  std::vector<int> ids;
  for (const std::string& part : parts) {
    ids.push_back(bop_object_id(part));
    if (ids.back() < 0)
      throw InputError(source, "obj_id",
                       "part '" + part + "' is no BOP model (obj_id N is part YCBV_NN): give the parts' start in a "
                       "demoplan-tracker-init file instead");
  }
  // Per frame, each model's best estimate.
  std::map<int, std::map<int, const BopDetection*>> best;
  for (const BopDetection& d : detections) {
    const BopDetection*& b = best[d.image_id][d.object_id];
    if (!b || d.score > b->score) b = &d;
  }
  int fullest = -1;
  size_t most = 0;
  for (const auto& [frame, found] : best) {
    size_t have = 0;
    for (const int id : ids) have += found.count(id);
    if (have == ids.size()) {
      TrackerInit init;
      init.frame = frame;
      for (size_t k = 0; k < parts.size(); ++k)
        init.parts.push_back({parts[k], world_T_camera * found.at(ids[k])->camera_T_object});
      return init;
    }
    if (have > most) most = have, fullest = frame;
  }
  if (fullest < 0) throw InputError(source, "", "no estimate of any of the parts");
  std::string missing;
  for (size_t k = 0; k < parts.size(); ++k)
    if (!best[fullest].count(ids[k])) missing += (missing.empty() ? "'" : ", '") + parts[k] + "'";
  throw InputError(source, "im_id " + std::to_string(fullest),
                   "no frame has an estimate of every part: this one, with the most (" + std::to_string(most) + " of " +
                       std::to_string(parts.size()) + "), lacks " + missing);
}

}  // namespace demoplan::perception
