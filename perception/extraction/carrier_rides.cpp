#include "perception/extraction/carrier_rides.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/geometry/box_faces.h"
#include "core/statistics.h"
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
// coordinate of its centre's projections, the upper one of an even count); none when no sample
// there is valid.
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
  return Eigen::Vector2d(order_statistic(us, us.size() / 2), order_statistic(vs, vs.size() / 2));
}

std::string px(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f px", v);
  return text;
}

}  // namespace

std::vector<FittedRide> fit_carrier_rides(const PoseTracks& tracks, const ContactAnalysis& contacts,
                                          const std::vector<TrackedPart>& parts, const Demonstration& settled,
                                          const Scene& scene, const SnapOptions& snap, const Camera& camera,
                                          const CarrierRideOptions& options, std::vector<std::string>* notes) {
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
      fitted.riders.push_back({o, pose, std::min(until, fitted.until)});  // the carrier moving again takes it along
    }
    Pose carrier_before = samples[from].pose;
    if (const auto on = snap_to_support(box_faces(parts[k].extent), carrier_before, furniture, snap))
      carrier_before = on->pose;
    const RideFit fit = fit_ride(camera, carrier_before, samples[to].pose, sightings, options);
    const std::string what = "part '" + parts[k].id + "', frames " + std::to_string(ride.start) + "-" +
                             std::to_string(ride.end) + ": ";
    const std::string riding = std::to_string(sightings.size()) + " parts on it";
    if (!fit.motion) {
      if (notes && fit.residual_px > options.max_residual_px)
        notes->push_back(what + "its ride and the " + riding + " do not fit one motion (" + px(fit.residual_px) +
                         " off): their rests after it are as tracked");
      else if (notes && fit.residual_px >= 0)
        notes->push_back(what + "the fit of its ride to the " + riding + " moves it farther from where its image puts "
                         "it than its depth can be off: their rests after it are as tracked");
      continue;
    }
    fitted.motion = *fit.motion;
    fitted.carrier_after = *fit.motion * carrier_before;
    if (notes) {
      const Eigen::Vector3d eye = camera.world_T_camera->translation();
      const double nearer = (samples[to].pose.translation() - eye).norm() - (fitted.carrier_after.translation() - eye).norm();
      notes->push_back(what + "its ride fitted to where the " + riding + " show (" + px(fit.residual_px) +
                       "): it ended " + std::to_string(static_cast<int>(std::lround(std::abs(nearer) * 1e3))) + " mm " +
                       (nearer >= 0 ? "nearer" : "farther") +
                       " than its own image puts it, and the parts on it rest where it took them");
    }
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
