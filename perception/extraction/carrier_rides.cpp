#include "perception/extraction/carrier_rides.h"

#include <algorithm>

#include "core/geometry/box_faces.h"
#include "core/scene/support.h"

namespace demoplan::perception {

namespace {

// The start of the first motion of `object` from `frame` on (its next grasp or ride), else `end`.
int next_motion(const ContactAnalysis& contacts, int object, int frame, int end) {
  for (const auto& m : contacts.motions_of(object))
    if (m.start >= frame) return m.start;
  return end;
}

// Where the image shows the track's part over frames [from, to] (the median of each
// coordinate of its centre's projections); none when no sample there is valid.
std::optional<Eigen::Vector2d> seen_at(const std::vector<PoseSample>& samples, int from, int to, const Camera& camera) {
  const Pose camera_T_world = camera.world_T_camera->inverse();
  std::vector<double> us, vs;
  for (int f = std::max(from, 0); f <= to && f < static_cast<int>(samples.size()); ++f) {
    if (!samples[f].valid) continue;
    const cv::Point2d q = camera.project(camera_T_world * samples[f].pose.translation());
    us.push_back(q.x);
    vs.push_back(q.y);
  }
  if (us.empty()) return std::nullopt;
  const auto median = [](std::vector<double>& v) {
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
  };
  return Eigen::Vector2d(median(us), median(vs));
}

}  // namespace

std::vector<FittedRide> fit_carrier_rides(const PoseTracks& tracks, const ContactAnalysis& contacts,
                                          const std::vector<TrackedPart>& parts, const Demonstration& settled,
                                          const Scene& scene, const SnapOptions& snap, const Camera& camera,
                                          const CarrierRideOptions& options) {
  std::vector<FittedRide> out;
  if (!camera.world_T_camera) return out;
  const auto furniture = furniture_support_polygons(scene);
  constexpr int kSettleFrames = 5;  // after the ride, the riders' image positions are taken over these
  for (const MotionInterval& ride : contacts.transports) {
    const size_t k = static_cast<size_t>(ride.object);
    if (k >= parts.size() || parts[k].planning || !ride.seen_at_rest_after) continue;
    // The carrier's last sample at rest before and first at rest after (the hand may hide it
    // as the ride starts).
    const auto& samples = tracks.samples[k];
    const int n = static_cast<int>(samples.size());
    int from = std::min(ride.start, n - 1), to = ride.end;
    while (from >= 0 && !samples[from].valid) --from;
    while (to < n && !samples[to].valid) ++to;
    if (from < 0 || to >= n) continue;
    // The last event before the ride holds the riders' settled rests on the carrier.
    int before = -1;
    for (size_t i = 0; i < settled.events.size(); ++i)
      if (settled.events[i].frame <= ride.start) before = static_cast<int>(i);
    if (before < 0) continue;

    FittedRide fitted{.carrier = k, .end = ride.end, .until = next_motion(contacts, ride.object, ride.end, n)};
    std::vector<RiderSighting> sightings;
    for (const MotionInterval& other : contacts.transports) {
      const size_t j = static_cast<size_t>(other.object);
      if (j >= parts.size() || !parts[j].planning || other.end < ride.start || other.start > ride.end) continue;
      const int o = settled.object_index(parts[j].id);
      if (o < 0 || !settled.events[before].pose_frame(o).empty()) continue;
      const int until = next_motion(contacts, other.object, other.end, n);
      const auto seen = seen_at(tracks.samples[j], other.end, std::min(until, other.end + kSettleFrames), camera);
      if (!seen) continue;
      const Pose& pose = settled.events[before].poses[o];
      sightings.push_back({pose.translation(), *seen});
      fitted.riders.push_back({o, pose, until});
    }
    Pose carrier_before = samples[from].pose;
    if (const auto on = snap_to_support(box_faces(parts[k].extent), carrier_before, furniture, snap))
      carrier_before = on->pose;
    const auto motion = fit_ride(camera, carrier_before, samples[to].pose, sightings, options);
    if (!motion) continue;
    fitted.motion = *motion;
    fitted.carrier_after = *motion * carrier_before;
    out.push_back(std::move(fitted));
  }
  return out;
}

void move_riders(Demonstration& d, const std::vector<FittedRide>& rides) {
  for (const FittedRide& ride : rides)
    for (auto& e : d.events)
      for (const RiderRest& rider : ride.riders)
        if (e.frame >= ride.end && e.frame <= rider.until && rider.object < static_cast<int>(e.poses.size()))
          e.poses[rider.object].translation() = ride.motion * rider.before.translation();
}

}  // namespace demoplan::perception
