#include "perception/events/track_segmentation.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "core/demo/rest_pose.h"
#include "core/statistics.h"

namespace demoplan::perception {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Longest run of samples a rest's centre and cost are computed from: longer rests are
// subsampled evenly, which keeps the segmentation quadratic in the video's length.
constexpr int kMaxSamples = 48;
// Longest piece the cut considers at once (frames); longer rests and motions are chains.
constexpr int kLongest = 200;
// Frames around a carrier's start or stop searched for where a carry onto or off it ends.
constexpr int kRideSearch = 6;

bool rigid(const Pose& p) {
  if (!p.matrix().allFinite()) return false;
  const Eigen::Matrix3d R = p.linear();
  return (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() < 1e-3 && R.determinant() > 0;
}

Eigen::Vector3d coordinate_median(const std::vector<Eigen::Vector3d>& points) {
  Eigen::Vector3d out;
  for (int k = 0; k < 3; ++k) {
    std::vector<double> v;
    v.reserve(points.size());
    for (const auto& p : points) v.push_back(p[k]);
    out[k] = median(std::move(v));
  }
  return out;
}

// One part's usable samples: position per frame (NaN where not usable).
struct Track {
  std::vector<bool> usable;
  std::vector<Eigen::Vector3d> position;  // world, m
  std::vector<Pose> pose;
  int count = 0;
  std::vector<Eigen::Vector3d> white;  // positions whitened by the track's noise
  std::vector<int> seen_frames;        // the usable frames, in order
  std::vector<int> seen_before;        // per frame, how many usable frames come before it
};

Track usable_track(const std::vector<PoseSample>& samples, int row, const std::string& id,
                   const TrackSegmentationOptions& o, std::vector<SegmentationDoubt>& doubts) {
  Track t;
  const int n = static_cast<int>(samples.size());
  t.usable.assign(n, false);
  t.position.assign(n, Eigen::Vector3d::Zero());
  t.pose.assign(n, Pose::Identity());
  std::vector<int> broken;
  for (int f = 0; f < n; ++f) {
    const PoseSample& s = samples[f];
    if (!s.valid || s.confidence < o.min_confidence) continue;
    if (!rigid(s.pose)) {
      broken.push_back(f);
      continue;
    }
    t.usable[f] = true;
    t.position[f] = s.pose.translation();
    t.pose[f] = s.pose;
    ++t.count;
  }
  if (!broken.empty()) {
    std::string frames;
    for (size_t k = 0; k < broken.size() && k < 5; ++k) frames += (k ? ", " : "") + std::to_string(broken[k]);
    if (broken.size() > 5) frames += " and " + std::to_string(broken.size() - 5) + " more";
    doubts.push_back({row, broken.front(), broken.back(),
                      id + ": frame" + (broken.size() > 1 ? "s " : " ") + frames +
                          ": the pose is not finite or its rotation not orthonormal; ignored"});
  }
  return t;
}

// The residuals of each sample to the median of its neighbours (two each side) carry the
// detector's noise without the motion; their spread per principal direction is the noise.
TrackNoise measure_noise(const Track& t, const TrackSegmentationOptions& o) {
  TrackNoise noise;
  noise.usable_frames = t.count;
  std::vector<Eigen::Vector3d> residuals;
  std::vector<double> angles;
  const int n = static_cast<int>(t.usable.size());
  for (int f = 0; f < n; ++f) {
    if (!t.usable[f]) continue;
    std::vector<Eigen::Vector3d> around;
    for (int g = std::max(0, f - 2); g <= std::min(n - 1, f + 2); ++g)
      if (t.usable[g]) around.push_back(t.position[g]);
    if (around.size() >= 3) residuals.push_back(t.position[f] - coordinate_median(around));
    for (int g = f + 1; g < n && g <= f + 2; ++g)
      if (t.usable[g]) {
        angles.push_back(log3(t.pose[f].linear().transpose() * t.pose[g].linear()).norm());
        break;
      }
  }
  const double floor2 = o.min_noise * o.min_noise;
  noise.covariance = Eigen::Matrix3d::Identity() * floor2;
  noise.sigma_max = noise.sigma_min = o.min_noise;
  noise.sigma_rotation = median(angles) / std::sqrt(2.0);
  if (residuals.size() < 5) return noise;
  std::vector<double> norms;
  for (const auto& r : residuals) norms.push_back(r.norm());
  const double typical = median(norms);
  Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();
  for (const auto& r : residuals)
    if (r.norm() <= 3.0 * typical) spread += r * r.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> axes(spread);
  Eigen::Vector3d sigma;
  for (int k = 0; k < 3; ++k) {
    std::vector<double> along;
    for (const auto& r : residuals) along.push_back(std::abs(r.dot(axes.eigenvectors().col(k))));
    // MAD to sigma; the neighbours' median moves with the sample, which hides about a fifth.
    sigma[k] = std::max(o.min_noise, 1.4826 * 1.2 * median(std::move(along)));
  }
  noise.covariance = axes.eigenvectors() * sigma.cwiseAbs2().asDiagonal() * axes.eigenvectors().transpose();
  noise.sigma_max = sigma.maxCoeff();
  noise.sigma_min = sigma.minCoeff();
  return noise;
}

struct Piece {
  bool rest = true;
  int first = 0, last = 0;
};

void whiten(Track& t, const TrackNoise& noise) {
  const Eigen::Matrix3d L = noise.covariance.llt().matrixL();
  t.white.assign(t.usable.size(), Eigen::Vector3d::Zero());
  t.seen_frames.clear();
  t.seen_before.assign(t.usable.size() + 1, 0);
  for (size_t f = 0; f < t.usable.size(); ++f) {
    t.seen_before[f + 1] = t.seen_before[f] + (t.usable[f] ? 1 : 0);
    if (!t.usable[f]) continue;
    t.white[f] = L.triangularView<Eigen::Lower>().solve(t.position[f]);
    t.seen_frames.push_back(static_cast<int>(f));
  }
}

// A rest's samples over [a, b) (every stride-th when long), whitened: at most kMaxSamples,
// picked without walking the frames, so that a cost is independent of the rest's length.
std::vector<Eigen::Vector3d> rest_samples(const Track& t, int a, int b) {
  const int first = t.seen_before[a], count = t.seen_before[b] - first;
  const int stride = std::max(1, (count + kMaxSamples - 1) / kMaxSamples);
  std::vector<Eigen::Vector3d> pts;
  pts.reserve(static_cast<size_t>(count / stride + 1));
  for (int k = 0; k < count; k += stride) pts.push_back(t.white[t.seen_frames[first + k]]);
  return pts;
}

std::vector<double> distances(const std::vector<Eigen::Vector3d>& pts, const Eigen::Vector3d& centre) {
  std::vector<double> d;
  for (const auto& p : pts) d.push_back((p - centre).norm());
  return d;
}

// The spread of a rest's samples about their median, in units of the track's noise (>= 1):
// the median distance over that of a unit 3D Gaussian (1.54).
double median_spread(std::vector<double> d) { return std::max(1.0, median(std::move(d)) / 1.54); }

// The same, or the 60th percentile's distance over 1.72 when larger: for the cut. A detector
// that holds one estimate for most of a rest (tunnel_0: six of ten samples within 0.8 mm, after
// its position estimate jumped 6 mm with an orientation flip) pins the median to them, and the
// rest's other samples would cost as much as moving.
double spread_of(const std::vector<Eigen::Vector3d>& pts, const Eigen::Vector3d& centre) {
  std::vector<double> d = distances(pts, centre);
  const double sixtieth = order_statistic(d, d.size() * 3 / 5);
  return std::max(median_spread(std::move(d)), sixtieth / 1.72);
}

double rest_spread(const Track& t, const TrackSegment& rest) {
  const auto pts = rest_samples(t, rest.first, rest.last + 1);
  return pts.empty() ? 1.0 : median_spread(distances(pts, coordinate_median(pts)));
}

// The optimal cut of frames [0, n) into alternating rests and motions (see the header). A rest
// costs each sample its negative log-likelihood under a Gaussian about the rest's median with
// the rest's own spread (capped for outliers): a quiet rest is cheap, a rest spread as wide as
// `max_rest_spread` costs as much as moving.
std::vector<Piece> cut(const Track& t, const TrackNoise& noise, const TrackSegmentationOptions& o) {
  const int n = static_cast<int>(t.usable.size());
  std::vector<int> seen(n + 1, 0);  // prefix counts of usable frames
  for (int f = 0; f < n; ++f) seen[f + 1] = seen[f] + (t.usable[f] ? 1 : 0);
  const double cap = o.outlier_sigmas * o.outlier_sigmas;
  // The widest rest in units of the noise, across the directions (their geometric mean).
  const double unit = std::cbrt(std::max(noise.covariance.determinant(), 1e-30));
  const double widest = std::max(1.0, o.max_rest_spread / std::sqrt(unit));
  const double motion_cost = 1.5 + 3.0 * std::log(widest);
  auto rest_cost = [&](int a, int b) {  // frames [a, b)
    const int count = seen[b] - seen[a];
    const double missing = o.missing_cost * ((b - a) - count);
    if (count == 0) return missing;
    if (count < o.min_rest_frames) return kInf;  // too short to tell a rest from a slow frame
    const auto pts = rest_samples(t, a, b);
    const Eigen::Vector3d centre = coordinate_median(pts);
    const double spread = spread_of(pts, centre);
    double sum = 0;
    for (const auto& p : pts) sum += 0.5 * std::min((p - centre).squaredNorm() / (spread * spread), cap);
    return (sum / static_cast<double>(pts.size()) + 3.0 * std::log(spread)) * count + missing;
  };
  // best[b][k]: cheapest cut of [0, b) whose last piece is a rest (k = 0) or a motion (k = 1).
  // A piece is at most kLongest frames; a longer rest or motion is a chain of pieces of exactly
  // kLongest and a last shorter one (joined again below), which keeps the cut linear in the
  // video's length and leaves shorter videos' cuts as they were.
  std::vector<std::array<double, 2>> best(n + 1, {kInf, kInf});
  std::vector<std::array<int, 2>> from(n + 1, {-1, -1}), from_kind(n + 1, {-1, -1});
  best[0] = {0.0, 0.0};
  for (int b = 1; b <= n; ++b)
    for (int a = std::max(0, b - kLongest); a < b; ++a) {
      // What may come before: the other kind, or a full-length piece of the same kind.
      for (int before = 0; before < 2; ++before) {
        if (a > 0 && best[a][before] == kInf) continue;
        const bool full = a > 0 && from[a][before] == a - kLongest;
        for (int kind = 0; kind < 2; ++kind) {
          if (a > 0 && before == kind && !full) continue;
          const bool continues = a > 0 && before == kind;
          const double piece = kind == 0 ? rest_cost(a, b)
                                         : motion_cost * (seen[b] - seen[a]) + (continues ? 0.0 : o.motion_penalty);
          const double total = (a == 0 ? 0.0 : best[a][before]) + piece;
          if (total < best[b][kind]) best[b][kind] = total, from[b][kind] = a, from_kind[b][kind] = a == 0 ? -1 : before;
        }
        if (a == 0) break;
      }
    }
  std::vector<Piece> pieces;
  int kind = best[n][0] <= best[n][1] ? 0 : 1;
  for (int b = n; b > 0;) {
    const int a = from[b][kind];
    if (!pieces.empty() && pieces.back().rest == (kind == 0))
      pieces.back().first = a;  // a chained piece: one rest or motion with the one after it
    else
      pieces.push_back({kind == 0, a, b - 1});
    kind = from_kind[b][kind];
    b = a;
  }
  std::reverse(pieces.begin(), pieces.end());
  return pieces;
}

Pose rest_pose_of(const Track& t, int first, int last) {
  PoseList samples;
  int count = 0;
  for (int f = first; f <= last; ++f) count += t.usable[f] ? 1 : 0;
  const int stride = std::max(1, (count + 199) / 200);  // the medoid rotation is quadratic
  int k = 0;
  for (int f = first; f <= last; ++f)
    if (t.usable[f] && k++ % stride == 0) samples.push_back(t.pose[f]);
  return robust_static_pose(samples);
}

int seen_in(const Track& t, int first, int last) {
  int count = 0;
  for (int f = std::max(first, 0); f <= last && f < static_cast<int>(t.usable.size()); ++f) count += t.usable[f];
  return count;
}

// Whether two rests lie far enough apart for a carry between them.
bool displaced(const Pose& a, const Pose& b, const TrackNoise& noise, const TrackSegmentationOptions& o,
               double scale = 1.0) {
  const Eigen::Vector3d d = b.translation() - a.translation();
  const double distance = d.norm();
  if (distance < 1e-12) return false;
  const Eigen::Vector3d u = d / distance;
  const double sigma = scale * std::sqrt(u.dot(noise.covariance * u));
  return distance > std::max(o.min_carry_distance, o.carry_sigmas * sigma);
}

// Rests and motions of one part, with rests too close together merged into one.
std::vector<TrackSegment> rests_and_motions(const Track& t, const TrackNoise& noise, const TrackSegmentationOptions& o) {
  std::vector<TrackSegment> segs;
  for (const Piece& p : cut(t, noise, o)) {
    // A rest never seen is no rest: its frames belong to the motion around it.
    const bool rest = p.rest && seen_in(t, p.first, p.last) > 0;
    if (!segs.empty() && (segs.back().kind == SegmentKind::Rest) == rest && !rest) {
      segs.back().last = p.last;
      continue;
    }
    TrackSegment s;
    s.kind = rest ? SegmentKind::Rest : SegmentKind::Moving;
    s.first = p.first;
    s.last = p.last;
    if (rest) s.pose = rest_pose_of(t, p.first, p.last);
    segs.push_back(s);
  }
  // Merge the least displaced pair of neighbouring rests first, until every pair is a carry apart.
  for (;;) {
    int merge = -1;
    double closest = kInf;
    for (size_t k = 0; k + 2 < segs.size(); ++k) {
      if (segs[k].kind != SegmentKind::Rest || segs[k + 2].kind != SegmentKind::Rest) continue;
      const double scale = std::max(rest_spread(t, segs[k]), rest_spread(t, segs[k + 2]));
      if (displaced(segs[k].pose, segs[k + 2].pose, noise, o, scale)) continue;
      const double d = (segs[k].pose.translation() - segs[k + 2].pose.translation()).norm();
      if (d < closest) closest = d, merge = static_cast<int>(k);
    }
    if (merge < 0) break;
    TrackSegment& r = segs[merge];
    r.last = segs[merge + 2].last;
    r.pose = rest_pose_of(t, r.first, r.last);
    segs.erase(segs.begin() + merge + 1, segs.begin() + merge + 3);
  }
  for (size_t k = 1; k + 1 < segs.size(); ++k)
    if (segs[k].kind == SegmentKind::Moving) {
      segs[k].kind = SegmentKind::Carry;
      segs[k].distance = (segs[k + 1].pose.translation() - segs[k - 1].pose.translation()).norm();
    }
  return segs;
}

// Position of a part around `frame`: the median of its usable samples within two frames.
std::optional<Eigen::Vector3d> position_near(const Track& t, int frame) {
  std::vector<Eigen::Vector3d> pts;
  for (int f = frame - 1; f <= frame + 1; ++f)
    if (f >= 0 && f < static_cast<int>(t.usable.size()) && t.usable[f]) pts.push_back(t.position[f]);
  if (pts.empty())
    for (int f = frame - 2; f <= frame + 2; f += 4)
      if (f >= 0 && f < static_cast<int>(t.usable.size()) && t.usable[f]) pts.push_back(t.position[f]);
  if (pts.empty()) return std::nullopt;
  return coordinate_median(pts);
}

struct Ride {
  int carrier = -1;
  int first = 0, last = 0;  // the carrier's last rest frame before, first rest frame after
};

// Whether part `o`'s motion [first, last] is, over some frames, a ride on another part's
// motion: the two move over overlapping frames by about the same displacement. The carrier is
// a part outside the plan (a tray) if one qualifies, else a planning part moving with it: parts
// that move together ride on a support, tracked or not (the hand carries one part at a time).
std::optional<Ride> find_ride(int o, const TrackSegment& motion, const std::vector<Track>& tracks,
                              const std::vector<std::vector<TrackSegment>>& segs, const std::vector<bool>& planning,
                              const TrackSegmentationOptions& opt) {
  std::optional<Ride> best;
  double best_rank = kInf;
  for (size_t c = 0; c < segs.size(); ++c) {
    if (static_cast<int>(c) == o) continue;
    for (const TrackSegment& m : segs[c]) {
      if (m.kind != SegmentKind::Carry && m.kind != SegmentKind::Ride) continue;
      const int first = std::max(motion.first, m.first) - 1, last = std::min(motion.last, m.last) + 1;
      if (last - first < 3) continue;
      const auto o0 = position_near(tracks[o], first), o1 = position_near(tracks[o], last);
      const auto c0 = position_near(tracks[c], first), c1 = position_near(tracks[c], last);
      if (!o0 || !o1 || !c0 || !c1) continue;
      const Eigen::Vector3d dc = *c1 - *c0, d_o = *o1 - *o0;
      // Only the displacement in the plane: a tray's track may carry no height at all.
      const double moved = dc.head<2>().norm();
      if (moved < opt.min_carry_distance) continue;
      if ((d_o - dc).head<2>().norm() > opt.ride_tolerance * moved) continue;
      const bool tray = !planning[c];
      const double rank = tray ? -1.0 : static_cast<double>(c);
      if (rank < best_rank) best_rank = rank, best = Ride{static_cast<int>(c), first, last};
    }
  }
  return best;
}

// Splits part `o`'s carry at index k around a ride: the piece before the ride stays a carry
// when it moves the part a carry's distance from its rest (it then ends where the ride starts),
// likewise the piece after.
void split_at_ride(std::vector<TrackSegment>& segs, size_t k, const Ride& ride, const Track& t, const TrackNoise& noise,
                   const TrackSegmentationOptions& o) {
  const TrackSegment motion = segs[k];
  const Pose before = segs[k - 1].pose, after = segs[k + 1].pose;
  std::vector<TrackSegment> pieces;
  int ride_first = std::max(ride.first, motion.first), ride_last = std::min(ride.last, motion.last);
  // Where a carry meets a ride there is no rest to end it; if the part stands still for a
  // frame near where the carrier starts (or stops) moving, the hand lets go (takes hold) there:
  // a carrier's track may start or stop a few frames off.
  auto slowest = [&](int from, int to) {
    int best = -1;
    double least = 3.0 * std::max(noise.sigma_max, o.min_noise);
    for (int f = std::max(from, 1); f <= to; ++f)
      if (t.usable[f] && t.usable[f - 1] && (t.position[f] - t.position[f - 1]).norm() < least)
        least = (t.position[f] - t.position[f - 1]).norm(), best = f;
    return best;
  };
  if (ride_first > motion.first) {
    Pose at = before;
    if (auto p = position_near(t, ride_first)) at.translation() = *p;
    if (displaced(before, at, noise, o, rest_spread(t, segs[k - 1]))) {
      if (const int f = slowest(std::max(motion.first + 1, ride_first - kRideSearch), ride_first); f > 0) ride_first = f;
      pieces.push_back({SegmentKind::Carry, motion.first, ride_first - 1, -1, Pose::Identity(),
                        (at.translation() - before.translation()).norm()});
    } else
      segs[k - 1].last = ride_first - 1;  // the start of the motion was noise of the rest
  }
  TrackSegment r{SegmentKind::Ride, ride_first, ride_last, ride.carrier, Pose::Identity(), 0.0};
  if (auto p0 = position_near(t, ride_first), p1 = position_near(t, ride_last); p0 && p1) r.distance = (*p1 - *p0).norm();
  pieces.push_back(r);
  if (ride_last < motion.last) {
    Pose at = after;
    if (auto p = position_near(t, ride_last)) at.translation() = *p;
    if (displaced(at, after, noise, o, rest_spread(t, segs[k + 1]))) {
      if (const int f = slowest(ride_last, std::min(motion.last - 1, ride_last + kRideSearch)); f > 0) {
        pieces.back().last = f;
        ride_last = f;
      }
      pieces.push_back({SegmentKind::Carry, ride_last + 1, motion.last, -1, Pose::Identity(),
                        (after.translation() - at.translation()).norm()});
    } else
      segs[k + 1].first = ride_last + 1;
  }
  if (pieces.front().kind == SegmentKind::Ride) pieces.front().first = segs[k - 1].last + 1;
  if (pieces.back().kind == SegmentKind::Ride) pieces.back().last = segs[k + 1].first - 1;
  segs.erase(segs.begin() + static_cast<long>(k));
  segs.insert(segs.begin() + static_cast<long>(k), pieces.begin(), pieces.end());
}

std::string frames_text(int first, int last) {
  return first == last ? "frame " + std::to_string(first) : "frames " + std::to_string(first) + "-" + std::to_string(last);
}

}  // namespace

const char* segment_kind_name(SegmentKind kind) {
  switch (kind) {
    case SegmentKind::Rest: return "rest";
    case SegmentKind::Carry: return "carry";
    case SegmentKind::Ride: return "ride";
    case SegmentKind::Moving: return "moving";
  }
  return "?";
}

TrackSegmentation segment_tracks(const PoseTracks& tracks, const TrackSegmentationOptions& o) {
  TrackSegmentation out;
  const size_t n = tracks.object_ids.size();
  // A part without a planning flag counts as a planning part.
  std::vector<bool> planning = tracks.planning;
  planning.resize(n, true);
  std::vector<Track> ts;
  std::vector<std::vector<TrackSegment>> segs(n);
  out.objects.resize(n);
  for (size_t i = 0; i < n; ++i) {
    std::vector<PoseSample> samples = i < tracks.samples.size() ? tracks.samples[i] : std::vector<PoseSample>{};
    samples.resize(static_cast<size_t>(std::max(tracks.frames, 0)));
    ts.push_back(usable_track(samples, static_cast<int>(i), tracks.object_ids[i], o, out.doubts));
    out.objects[i].noise = measure_noise(ts[i], o);
    whiten(ts[i], out.objects[i].noise);
    if (ts[i].count == 0) {
      if (tracks.frames > 0) {
        segs[i] = {{SegmentKind::Moving, 0, tracks.frames - 1}};
        out.doubts.push_back({static_cast<int>(i), 0, tracks.frames - 1, tracks.object_ids[i] + " is never seen"});
      }
      continue;
    }
    segs[i] = rests_and_motions(ts[i], out.objects[i].noise, o);
  }
  // Rides: a part moving with a carrier keeps its place on it.
  for (size_t i = 0; i < n; ++i)
    for (size_t k = 1; k + 1 < segs[i].size(); ++k) {
      if (segs[i][k].kind != SegmentKind::Carry) continue;
      if (auto ride = find_ride(static_cast<int>(i), segs[i][k], ts, segs, planning, o)) {
        split_at_ride(segs[i], k, *ride, ts[i], out.objects[i].noise, o);
        ++k;
      }
    }
  // One hand: of two planning parts carried over the same frames, the one carried farther is.
  struct Ref {
    size_t object, index;
  };
  std::vector<Ref> carries;
  for (size_t i = 0; i < n; ++i)
    for (size_t k = 0; k < segs[i].size(); ++k)
      if (planning[i] && segs[i][k].kind == SegmentKind::Carry) carries.push_back({i, k});
  for (const Ref& a : carries)
    for (const Ref& b : carries) {
      TrackSegment& x = segs[a.object][a.index];
      TrackSegment& y = segs[b.object][b.index];
      if (a.object == b.object || x.kind != SegmentKind::Carry || y.kind != SegmentKind::Carry) continue;
      // A carry's grasp and release frames are the rest frames around its motion.
      if (x.last + 1 <= y.first - 1 || y.last + 1 <= x.first - 1) continue;
      // Carries that overlap at their ends only: the noise blurs where one part comes to rest
      // and the next starts moving. The hand passes from one to the other midway.
      TrackSegment& early = x.first <= y.first ? x : y;
      TrackSegment& late = x.first <= y.first ? y : x;
      const int overlap = early.last + 1 - (late.first - 1) + 1;
      const int shorter = std::min(early.last - early.first, late.last - late.first) + 1;
      if (late.last > early.last && 3 * overlap <= shorter) {
        const int middle = (late.first - 1 + early.last + 1) / 2;
        early.last = middle - 1;  // released at `middle`
        late.first = middle + 2;  // grasped the frame after
        continue;
      }
      TrackSegment& loser = x.distance < y.distance ? x : y;
      const size_t lo = x.distance < y.distance ? a.object : b.object;
      const size_t hi = x.distance < y.distance ? b.object : a.object;
      loser.kind = SegmentKind::Moving;
      out.doubts.push_back({static_cast<int>(lo), loser.first, loser.last,
                            tracks.object_ids[lo] + " moves " + std::to_string(static_cast<int>(loser.distance * 1000)) +
                                " mm while " + tracks.object_ids[hi] +
                                " is carried: one hand carries one part at a time; its move is not taken as a carry"});
    }
  for (size_t i = 0; i < n; ++i) {
    const auto& s = segs[i];
    for (size_t k = 0; k < s.size(); ++k) {
      const TrackSegment& m = s[k];
      if (m.kind == SegmentKind::Rest || m.kind == SegmentKind::Ride) continue;
      const std::string& id = tracks.object_ids[i];
      if (k == 0 && m.kind == SegmentKind::Moving && ts[i].count > 0)
        out.doubts.push_back({static_cast<int>(i), m.first, m.last,
                              id + " moves from the start of the video (" + frames_text(m.first, m.last) +
                                  "): where it was picked up is not seen"});
      else if (k + 1 == s.size() && m.kind == SegmentKind::Moving && ts[i].count > 0)
        out.doubts.push_back({static_cast<int>(i), m.first, m.last,
                              id + " still moves when the video ends (" + frames_text(m.first, m.last) +
                                  "): the carry ends nowhere"});
      else if (m.kind == SegmentKind::Carry && seen_in(ts[i], m.first, m.last) == 0 && planning[i])
        out.doubts.push_back({static_cast<int>(i), m.first, m.last,
                              id + " is seen resting at two places with no motion between (" +
                                  frames_text(m.first, m.last) + " unseen): a carry is assumed"});
    }
    // A part that leaves the view for good (carried away, or its track ends early) ends nowhere.
    int last_seen = -1;
    for (int f = 0; f < static_cast<int>(ts[i].usable.size()); ++f)
      if (ts[i].usable[f]) last_seen = f;
    if (last_seen >= 0 && tracks.frames - 1 - last_seen > o.max_unseen_end)
      out.doubts.push_back({static_cast<int>(i), last_seen + 1, tracks.frames - 1,
                            tracks.object_ids[i] + " is not seen after frame " + std::to_string(last_seen) +
                                ": where it ends is not known (taken to stay where it was last seen resting)"});
    out.objects[i].segments = s;
  }
  std::sort(out.doubts.begin(), out.doubts.end(), [](auto& a, auto& b) { return a.first < b.first; });
  return out;
}

ContactAnalysis TrackSegmentation::contacts(const PoseTracks& tracks) const {
  ContactAnalysis c;
  for (size_t i = 0; i < objects.size(); ++i) {
    c.jitter_translation.push_back(objects[i].noise.sigma_max);
    c.jitter_rotation.push_back(objects[i].noise.sigma_rotation);
    const auto& s = objects[i].segments;
    for (size_t k = 0; k < s.size(); ++k) {
      // Grasp: the last frame at rest before; release: the first frame at rest after.
      const MotionInterval m{static_cast<int>(i), std::max(s[k].first - 1, 0),
                             std::min(s[k].last + 1, std::max(tracks.frames - 1, 0)), 1.0, 1.0, s[k].distance};
      if (s[k].kind == SegmentKind::Carry && (i >= tracks.planning.size() || tracks.planning[i])) c.carries.push_back(m);
      if (s[k].kind == SegmentKind::Ride) c.transports.push_back(m);
      if (s[k].kind == SegmentKind::Moving && k > 0 && k + 1 < s.size()) c.rejected.push_back(m);
    }
  }
  auto by_start = [](const MotionInterval& a, const MotionInterval& b) { return a.start < b.start; };
  std::sort(c.carries.begin(), c.carries.end(), by_start);
  std::sort(c.transports.begin(), c.transports.end(), by_start);
  std::sort(c.rejected.begin(), c.rejected.end(), by_start);
  return c;
}

}  // namespace demoplan::perception
