#include "perception/events/contact_detector.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>

#include "core/demo/rest_pose.h"
#include "core/statistics.h"

namespace demoplan::perception {

namespace {

double angle_between(const Pose& a, const Pose& b) {
  return Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle();
}

// Where the samples are, robust to a few outliers (the same average as the event poses').
Pose centre_of(const std::vector<const PoseSample*>& s) {
  PoseList poses;
  for (const auto* p : s) poses.push_back(p->pose);
  return robust_static_pose(poses);
}

struct Thresholds {
  double rest_t, rest_r, move_t, move_r;
};

bool overlaps(const MotionInterval& a, const MotionInterval& b) { return a.start < b.end && b.start < a.end; }

// Whether two parts kept their relative position while both moved.
bool move_together(const PoseTracks& tracks, const MotionInterval& a, const MotionInterval& b, double tolerance) {
  const int f0 = std::max(a.start, b.start), f1 = std::min(a.end, b.end);
  std::vector<Eigen::Vector3d> rel;
  for (int f = f0; f <= f1; ++f) {
    const PoseSample& sa = tracks.samples[a.object][f];
    const PoseSample& sb = tracks.samples[b.object][f];
    if (sa.valid && sb.valid) rel.push_back(sa.pose.inverse() * sb.pose.translation());
  }
  if (rel.size() < 3) return false;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& r : rel) mean += r / static_cast<double>(rel.size());
  for (const auto& r : rel)
    if ((r - mean).norm() > tolerance) return false;
  return true;
}

// Whether two parts were moved alike over the frames both moved: each far enough for a carry,
// their displacements apart by at most `fraction` of the longer. A tray that turns as it goes
// parts their displacements by their separation times the turn; and the relative position in
// one part's frame (move_together) swings by the separation times that part's orientation
// error, centimetres for small parts a few metres from the camera. A hand dragging a second part
// along moves it much less than the one it carries.
bool displaced_alike(const PoseTracks& tracks, const MotionInterval& a, const MotionInterval& b, double fraction,
                     double min_distance) {
  const int f0 = std::max(a.start, b.start), f1 = std::min(a.end, b.end);
  auto both_seen = [&](int f) { return tracks.samples[a.object][f].valid && tracks.samples[b.object][f].valid; };
  int first = f0, last = f1;
  while (first < last && !both_seen(first)) ++first;
  while (last > first && !both_seen(last)) --last;
  if (last - first < 2) return false;
  auto displacement = [&](int object) {
    return Eigen::Vector3d(tracks.samples[object][last].pose.translation() -
                           tracks.samples[object][first].pose.translation());
  };
  const Eigen::Vector3d da = displacement(a.object), db = displacement(b.object);
  const double longer = std::max(da.norm(), db.norm());
  return std::min(da.norm(), db.norm()) >= min_distance && (da - db).norm() <= fraction * longer;
}

}  // namespace

std::vector<MotionInterval> ContactAnalysis::motions_of(int object) const {
  std::vector<MotionInterval> out;
  for (const auto* list : {&carries, &transports})
    for (const auto& m : *list)
      if (m.object == object) out.push_back(m);
  std::sort(out.begin(), out.end(), [](auto& a, auto& b) { return a.start < b.start; });
  return out;
}

std::vector<bool> usable_samples(const std::vector<PoseSample>& samples, const ContactDetectorOptions& o) {
  std::vector<double> rms;
  for (const auto& s : samples)
    if (s.valid && s.markers > 0) rms.push_back(s.reprojection_px);
  const double max_rms = std::max(0.6, o.outlier_reprojection * median(rms));
  std::vector<bool> out(samples.size(), false);
  for (size_t f = 0; f < samples.size(); ++f) {
    const PoseSample& s = samples[f];
    out[f] = s.valid && s.confidence >= o.min_confidence && (s.markers == 0 || s.reprojection_px <= max_rms);
  }
  return out;
}

std::vector<MotionInterval> detect_motions(const std::vector<PoseSample>& samples, int object,
                                           const ContactDetectorOptions& o, double* jitter_t, double* jitter_r) {
  const std::vector<bool> usable = usable_samples(samples, o);
  std::vector<int> frames;
  for (int f = 0; f < static_cast<int>(samples.size()); ++f)
    if (usable[f]) frames.push_back(f);
  std::vector<MotionInterval> out;
  if (frames.size() < 2) return out;
  auto at = [&](int i) -> const PoseSample& { return samples[frames[i]]; };

  // Jitter from second differences over three consecutive frames: a smooth motion hardly
  // changes its velocity from frame to frame, noise does. For Gaussian noise of sigma per axis
  // the second difference has sigma * sqrt(6) per axis, and the median norm of three such
  // axes is about 1.54 of that.
  std::vector<double> d2t, d2r;
  for (size_t i = 1; i + 1 < frames.size(); ++i) {
    if (frames[i] - frames[i - 1] != 1 || frames[i + 1] - frames[i] != 1) continue;
    const Pose &a = at(i - 1).pose, &b = at(i).pose, &c = at(i + 1).pose;
    d2t.push_back((c.translation() - 2 * b.translation() + a.translation()).norm());
    d2r.push_back((log3(b.linear().transpose() * c.linear()) - log3(a.linear().transpose() * b.linear())).norm());
  }
  constexpr double kSecondDifference = 1.54 * 2.449;
  // Estimators also drift slowly while a part rests (correlated errors the second difference
  // does not see): the frame-to-frame change of the calmer third of the frames (the parts
  // rest most of the time), for Gaussian steps of sigma * sqrt(2) per axis.
  std::vector<double> d1t, d1r;
  for (size_t i = 1; i < frames.size(); ++i)
    if (frames[i] - frames[i - 1] == 1) {
      d1t.push_back((at(i).pose.translation() - at(i - 1).pose.translation()).norm());
      d1r.push_back(angle_between(at(i).pose, at(i - 1).pose));
    }
  auto quantile = [](const std::vector<double>& v, double q) {
    return order_statistic(v, static_cast<size_t>(q * static_cast<double>(std::max<size_t>(v.size(), 1) - 1)));
  };
  constexpr double kFirstDifference = 1.1 * 1.414;  // the 33rd percentile of a chi(3) is about 1.1
  const double sigma_t = std::max(median(d2t) / kSecondDifference, quantile(d1t, 0.33) / kFirstDifference);
  const double sigma_r = std::max(median(d2r) / kSecondDifference, quantile(d1r, 0.33) / kFirstDifference);
  if (jitter_t) *jitter_t = sigma_t;
  if (jitter_r) *jitter_r = sigma_r;
  Thresholds th;
  th.rest_t = std::max(o.rest_translation, o.noise_factor * sigma_t);
  th.rest_r = std::max(o.rest_rotation, o.noise_factor * sigma_r);
  th.move_t = std::max(o.move_translation, 2.5 * th.rest_t);
  th.move_r = std::max(o.move_rotation, 2.5 * th.rest_r);
  // A sample less precise than the track's usual (fewer, smaller or farther markers) widens the
  // jitter's share of both thresholds by as much: its expected precision relative to the track's
  // median (the floors stay). As it is, the expected precision is an absolute accuracy (one 30 mm
  // marker 2 m away: 17 mm along the line of sight), and a resting part seen through the same
  // markers keeps the same error from frame to frame, so only the measured jitter counts then.
  // Seen through other markers than the reference was, the estimate may jump by that accuracy,
  // so it counts too.
  auto median_positive = [&](auto field) {
    std::vector<double> v;
    for (int f : frames)
      if (samples[f].*field > 0) v.push_back(samples[f].*field);
    return median(v);
  };
  const double usual_t = median_positive(&PoseSample::sigma_translation);
  const double usual_r = median_positive(&PoseSample::sigma_rotation);
  auto widening_t = [&](const PoseSample& p) { return usual_t > 0 ? std::max(1.0, p.sigma_translation / usual_t) : 1.0; };
  auto widening_r = [&](const PoseSample& p) { return usual_r > 0 ? std::max(1.0, p.sigma_rotation / usual_r) : 1.0; };
  // Whether `p` is off `ref` by more than `floor_t` / `floor_r`, `jitters` times the measured
  // jitter widened for `p`, and, unless `same_view` (`ref` comes from samples of the same markers
  // fitting as well as `p`, whose error `p` shares), `sigmas` times its expected precision.
  auto off = [&](const PoseSample& p, const Pose& ref, bool same_view, double floor_t, double floor_r, double jitters,
                 double sigmas) {
    const double tol_t = std::max({floor_t, jitters * sigma_t * widening_t(p), same_view ? 0.0 : sigmas * p.sigma_translation});
    const double tol_r = std::max({floor_r, jitters * sigma_r * widening_r(p), same_view ? 0.0 : sigmas * p.sigma_rotation});
    return (p.pose.translation() - ref.translation()).norm() > tol_t || angle_between(p.pose, ref) > tol_r;
  };
  auto still = [&](const PoseSample& p, const Pose& ref, bool same_view, double scale = 1.0) {
    return !off(p, ref, same_view, scale * th.rest_t, scale * th.rest_r, scale * o.noise_factor, scale * o.sigma_factor);
  };
  auto beyond = [&](const PoseSample& p, const Pose& ref, bool same_view) {
    return off(p, ref, same_view, th.move_t, th.move_r, 2.5 * o.noise_factor, 2.5 * o.sigma_factor);
  };
  auto same_view = [](const PoseSample& a, const PoseSample& b) {
    return a.marker_set != 0 && a.marker_set == b.marker_set &&
           std::abs(a.reprojection_px - b.reprojection_px) <= 0.1 + 0.5 * std::max(a.reprojection_px, b.reprojection_px);
  };

  const int n = static_cast<int>(frames.size());
  std::vector<int> rest{0}, moving;
  // Whether moving[a..b) still drifts: its least-squares velocity is above rest_velocity and
  // above what the noise explains (3 standard deviations of the fitted slope). A slow last
  // approach stays within the rest thresholds of noisy tracks but keeps its direction.
  auto drifting = [&](int a, int b) {
    double fm = 0;
    Eigen::Vector3d pm = Eigen::Vector3d::Zero();
    double sigma = sigma_t;
    for (int k = a; k < b; ++k) {
      fm += frames[moving[k]];
      pm += at(moving[k]).pose.translation();
      sigma = std::max(sigma, sigma_t * widening_t(at(moving[k])));
    }
    fm /= (b - a);
    pm /= (b - a);
    double den = 0;
    Eigen::Vector3d num = Eigen::Vector3d::Zero();
    for (int k = a; k < b; ++k) {
      const double df = frames[moving[k]] - fm;
      num += df * (at(moving[k]).pose.translation() - pm);
      den += df * df;
    }
    if (den <= 0) return false;
    return (num / den).norm() > std::max(o.rest_velocity, 3.0 * sigma / std::sqrt(den));
  };
  Pose ref = at(0).pose, start_ref = ref;
  bool in_motion = false;
  int run = 0;
  int first_beyond = 0;  // index in `moving` of the first sample beyond the rest
  MotionInterval cur;
  cur.object = object;
  int first_moving = 0;  // first frame the current motion was seen moving
  // Last seen at rest, next seen moving: it was picked up while hidden, in the gap.
  auto place_hidden_grasp = [&] {
    const int gap = first_moving - cur.start;
    if (gap > 1) cur.start = first_moving - static_cast<int>(std::lround(o.hidden_event_fraction * gap));
  };
  // The rest's recent samples (the last kRecent) that `keep` accepts.
  constexpr size_t kRecent = 30;
  auto recent_rest = [&](auto keep) {
    std::vector<const PoseSample*> tail;
    for (size_t k = rest.size() > kRecent ? rest.size() - kRecent : 0; k < rest.size(); ++k)
      if (keep(at(rest[k]))) tail.push_back(&at(rest[k]));
    return tail;
  };
  auto rest_centre = [&]() { return centre_of(recent_rest([](const PoseSample&) { return true; })); };
  // The centre of moving[end - count, end) when those samples sit still about it.
  auto still_window = [&](int end, int count) -> std::optional<Pose> {
    std::vector<const PoseSample*> window;
    for (int k = end - count; k < end; ++k) window.push_back(&at(moving[k]));
    const Pose centre = centre_of(window);
    for (const auto* w : window)
      if (!still(*w, centre, same_view(*w, *window.back()))) return std::nullopt;
    return centre;
  };
  for (int i = 1; i < n; ++i) {
    const PoseSample& p = at(i);
    if (!in_motion) {
      // The rest pose as the sample's own markers saw it, when they did twice or more: their
      // error is the same, so only the jitter tells them apart. Else the rest pose of all. (When
      // every recent rest sample saw it alike, that is `ref` itself: ref is rest_centre().)
      const std::vector<const PoseSample*> same = recent_rest([&](const PoseSample& r) { return same_view(r, p); });
      const bool seen_alike = same.size() >= 2;
      const bool all_alike = same.size() == std::min(rest.size(), kRecent);
      const Pose seen_ref = seen_alike && !all_alike ? centre_of(same) : ref;
      if (still(p, seen_ref, seen_alike)) {
        rest.push_back(i);
        moving.clear();
        run = 0;
        ref = rest_centre();
        continue;
      }
      moving.push_back(i);
      if (beyond(p, seen_ref, seen_alike) && run++ == 0) first_beyond = static_cast<int>(moving.size()) - 1;
      if (run < o.min_moving_frames) {
        // Samples that settle a little off the rest pose (it was estimated from few or poor
        // samples) make the rest pose anew.
        const int m = static_cast<int>(moving.size());
        if (m >= o.min_rest_frames) {
          PoseSample c;
          const std::optional<Pose> centre = still_window(m, o.min_rest_frames);
          if (centre) c.pose = *centre;
          if (centre && !beyond(c, ref, false)) {
            rest.assign(moving.end() - o.min_rest_frames, moving.end());
            ref = rest_centre();
            moving.clear();
            run = 0;
          }
        }
        continue;
      }
      in_motion = true;
      start_ref = ref;
      int last_rest = rest.back();
      // Samples that sat still among themselves right before the first one beyond the rest are
      // the rest's last frames, seen through other or partly hidden markers (the hand arriving).
      if (first_beyond >= o.min_rest_frames && still_window(first_beyond, o.min_rest_frames)) last_rest = moving[first_beyond - 1];
      // So are fewer of them (as many as confirm a move), seen in a row and not drifting: an
      // estimate that jumped as the hand arrived, then sat still until the hand took the part.
      else if (first_beyond >= o.min_moving_frames && frames[moving[first_beyond - 1]] - frames[moving[0]] == first_beyond - 1 &&
               still_window(first_beyond, first_beyond) && !drifting(0, first_beyond))
        last_rest = moving[first_beyond - 1];
      cur.start = frames[last_rest];
      // A part hidden just before it moved: its grasp frame is uncertain.
      const int gap = frames[moving.front()] - frames[last_rest];
      // The first frame of two seen moving in a row (a lone glimpse does not end the gap).
      first_moving = frames[moving.front()];
      for (size_t k = 0; k + 1 < moving.size(); ++k)
        if (frames[moving[k + 1]] - frames[moving[k]] == 1) {
          first_moving = frames[moving[k]];
          break;
        }
      cur.start_confidence = at(last_rest).confidence * std::exp(-(gap - 1) / 10.0);
      cur.distance = 0;
      for (int k : moving) cur.distance = std::max(cur.distance, (at(k).pose.translation() - start_ref.translation()).norm());
      continue;
    }
    moving.push_back(i);
    cur.distance = std::max(cur.distance, (p.pose.translation() - start_ref.translation()).norm());
    const int m = static_cast<int>(moving.size());
    if (m < o.min_rest_frames) continue;
    const std::optional<Pose> settled = drifting(m - o.min_rest_frames, m) ? std::nullopt : still_window(m, o.min_rest_frames);
    if (!settled) continue;
    const Pose centre = *settled;
    // At rest again: it came to rest at the earliest sample that is still at the new pose
    // (closer than for staying at rest: the last slow approach is not rest yet).
    int j = m - o.min_rest_frames;
    const PoseSample& last = at(moving[m - 1]);
    while (j > 0 && still(at(moving[j - 1]), centre, same_view(at(moving[j - 1]), last), 0.6)) --j;
    cur.end = frames[moving[j]];
    const int gap = j > 0 ? frames[moving[j]] - frames[moving[j - 1]] : 1;
    // Last seen moving, next seen at rest: it was set down while hidden, in the gap. Lone
    // glimpses inside the gap (a marker corner between the fingers) do not end it: it runs from
    // the last frame of two seen in a row. (A carry hidden from end to end, j = 0, keeps the
    // frames it was last and first seen at rest.)
    if (j > 0) {
      int k = j - 1;
      while (k > 0 && frames[moving[k]] - frames[moving[k - 1]] > 1) --k;
      const int hidden = frames[moving[j]] - frames[moving[k]];
      // Seen before the gap where it comes to rest already (its place within the move threshold
      // of the rest's; not its turn: a hand over it turns its estimate, tunnel_0 with the
      // occluder 9.5 degrees off at 69), it was set down as the gap began.
      const bool seen_there = o.set_down_where_seen &&
                              (at(moving[k]).pose.translation() - centre.translation()).norm() <= th.move_t;
      if (hidden > 1)
        cur.end = frames[moving[k]] + (seen_there ? 1 : static_cast<int>(std::lround(o.hidden_event_fraction * hidden)));
      place_hidden_grasp();
    }
    cur.end_confidence = at(moving[j]).confidence * std::exp(-(gap - 1) / 10.0);
    const bool displaced = (centre.translation() - start_ref.translation()).norm() > th.move_t ||
                           angle_between(centre, start_ref) > th.move_r;
    // No hand carries a part in a blink: shorter motions are estimation jumps (the rest goes on,
    // at the pose the samples settle to).
    const bool long_enough = cur.end - cur.start >= o.min_carry_frames;
    if (long_enough && (displaced || cur.distance >= o.min_carry_distance)) out.push_back(cur);
    rest.assign(moving.begin() + j, moving.end());
    ref = rest_centre();
    moving.clear();
    run = 0;
    in_motion = false;
  }
  if (in_motion) place_hidden_grasp();
  if (in_motion && frames.back() - cur.start >= o.min_carry_frames) {
    cur.end = frames.back();  // still moving at the end of the video: it rests at its last sample
    cur.end_confidence = 0.3;
    cur.seen_at_rest_after = false;
    out.push_back(cur);
  }
  return out;
}

ContactAnalysis detect_contacts(const PoseTracks& tracks, const ContactDetectorOptions& o) {
  ContactAnalysis a;
  const int n = static_cast<int>(tracks.object_ids.size());
  a.jitter_translation.assign(n, 0.0);
  a.jitter_rotation.assign(n, 0.0);
  std::vector<MotionInterval> all;
  for (int k = 0; k < n; ++k) {
    auto m = detect_motions(tracks.samples[k], k, o, &a.jitter_translation[k], &a.jitter_rotation[k]);
    all.insert(all.end(), m.begin(), m.end());
  }
  std::sort(all.begin(), all.end(), [](auto& x, auto& y) { return x.start < y.start; });
  // One hand: a part whose motion runs on unseen into another part's grasp, seen taken, was set
  // down in its gap before that grasp (the hand was free for it): its release is put there
  // (hidden_event_fraction of the way from where it was last seen), not after the other's carry.
  std::vector<std::vector<bool>> usable(n);
  for (int k = 0; k < n; ++k) usable[k] = usable_samples(tracks.samples[k], o);
  for (MotionInterval& x : all) {
    if (!tracks.planning[x.object]) continue;
    // The last frame x is seen in its motion (a clip below keeps it: the frames cut were unseen).
    int last_seen = std::min(x.end, static_cast<int>(usable[x.object].size())) - 1;
    while (last_seen > x.start && !usable[x.object][last_seen]) --last_seen;
    for (const MotionInterval& y : all) {
      if (x.object == y.object || !tracks.planning[y.object] || y.start <= x.start || y.start <= last_seen ||
          !overlaps(x, y) || y.start >= static_cast<int>(usable[y.object].size()) || !usable[y.object][y.start] ||
          move_together(tracks, x, y, o.co_motion_tolerance))
        continue;
      const int end = last_seen + std::max(1, static_cast<int>(std::lround(o.hidden_event_fraction * (y.start - last_seen))));
      if (end - x.start < o.min_carry_frames) continue;  // too short for a carry: an estimate's jump
      x.end = end;
      x.end_confidence = std::min(x.end_confidence, 0.5);
    }
  }
  // Groups of motions that overlap in time.
  std::vector<bool> done(all.size(), false);
  for (size_t i = 0; i < all.size(); ++i) {
    if (done[i]) continue;
    std::vector<size_t> group{i};
    done[i] = true;
    for (size_t g = 0; g < group.size(); ++g)
      for (size_t j = 0; j < all.size(); ++j)
        if (!done[j] && overlaps(all[group[g]], all[j])) {
          done[j] = true;
          group.push_back(j);
        }
    std::vector<bool> together(group.size(), false);
    for (size_t x = 0; x < group.size(); ++x)
      for (size_t y = x + 1; y < group.size(); ++y) {
        const auto& mx = all[group[x]];
        const auto& my = all[group[y]];
        if (mx.object != my.object && overlaps(mx, my) && (move_together(tracks, mx, my, o.co_motion_tolerance) ||
                                                      displaced_alike(tracks, mx, my, o.co_motion_displacement,
                                                                      o.min_carry_distance)))
          together[x] = together[y] = true;
      }
    // The hand carries one part at a time: the parts that moved farthest, without overlaps.
    std::vector<size_t> order;
    for (size_t x = 0; x < group.size(); ++x)
      if (!together[x] && tracks.planning[all[group[x]].object]) order.push_back(x);
    std::sort(order.begin(), order.end(), [&](size_t x, size_t y) { return all[group[x]].distance > all[group[y]].distance; });
    std::vector<bool> carried(group.size(), false);
    for (size_t x : order) {
      bool free = true;
      for (size_t y = 0; y < group.size(); ++y) free = free && !(carried[y] && overlaps(all[group[x]], all[group[y]]));
      carried[x] = free;
    }
    for (size_t x = 0; x < group.size(); ++x) {
      const auto& m = all[group[x]];
      if (carried[x]) a.carries.push_back(m);
      else if (together[x] || !tracks.planning[m.object]) a.transports.push_back(m);
      else a.rejected.push_back(m);
    }
  }
  std::sort(a.carries.begin(), a.carries.end(), [](auto& x, auto& y) { return x.start < y.start; });
  return a;
}

}  // namespace demoplan::perception
