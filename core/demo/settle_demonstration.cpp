#include "core/demo/settle_demonstration.h"

#include <cmath>

#include "core/scene/support.h"

namespace demoplan {

Demonstration settle_on_supports(const Scene& scene, Demonstration d, const SettleOptions& options,
                                 const EventSupports& moving) {
  const auto furniture = furniture_support_polygons(scene);
  // The demonstration's parts by id (an extraction lists them in its marker scene's order).
  std::vector<std::vector<std::vector<Eigen::Vector3d>>> faces(d.object_ids.size());
  for (size_t o = 0; o < d.object_ids.size(); ++o)
    for (const auto& so : scene.objects)
      if (so.id == d.object_ids[o]) faces[o] = object_contact_polygons(so);
  SnapOptions onto_moving = options.snap;
  onto_moving.max_distance = options.moving_max_distance;
  for (size_t i = 0; i < d.events.size(); ++i) {
    auto& e = d.events[i];
    for (size_t o = 0; o < e.poses.size() && o < faces.size(); ++o) {
      if (faces[o].empty() || !e.pose_frame(static_cast<int>(o)).empty()) continue;
      auto snapped = snap_to_support(faces[o], e.poses[o], furniture, options.snap);
      // Onto a moving support when there is none of the furniture that near, or it is nearer (a
      // part on a tray on a table is within centimetres of both tops).
      if (i < moving.size())
        if (const auto on_top = snap_to_support(faces[o], e.poses[o], moving[i], onto_moving);
            on_top && (!snapped || std::abs(on_top->shift) < std::abs(snapped->shift)))
          snapped = on_top;
      if (snapped) e.poses[o] = snapped->pose;
    }
  }
  return d;
}

}  // namespace demoplan
