#include "perception/events/hand_fusion.h"

#include <algorithm>
#include <cmath>

namespace demoplan::perception {

namespace {

// The part's pixel box at a frame, from its nearest sample; `age` is how many frames away.
std::optional<cv::Rect2d> projected_box(const PoseTracks& tracks, int row, int frame, const Eigen::AlignedBox3d& bounds,
                                        const Camera& camera, int& age) {
  const auto& s = tracks.samples[row];
  const Pose camera_T_world = camera.world_T_camera->inverse();
  for (int d = 0; d < tracks.frames; ++d)
    for (int f : {frame - d, frame + d}) {
      if (f < 0 || f >= tracks.frames || !s[f].valid) continue;
      double x0 = 1e18, y0 = 1e18, x1 = -1e18, y1 = -1e18;
      for (int c = 0; c < 8; ++c) {
        const Eigen::Vector3d p = camera_T_world * (s[f].pose * bounds.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c)));
        if (p.z() <= 0.05) return std::nullopt;
        const cv::Point2d q = camera.project(p);
        x0 = std::min(x0, q.x), y0 = std::min(y0, q.y), x1 = std::max(x1, q.x), y1 = std::max(y1, q.y);
      }
      age = d;
      return cv::Rect2d(x0, y0, x1 - x0, y1 - y0);
    }
  return std::nullopt;
}

double iou(const cv::Rect2d& a, const cv::Rect2d& b) {
  const double i = (a & b).area();
  const double u = a.area() + b.area() - i;
  return u > 0 ? i / u : 0.0;
}

bool overlaps(int a0, int a1, int b0, int b1) { return a0 < b1 && b0 < a1; }

}  // namespace

std::vector<HandContactRun> hand_contact_runs(const std::vector<HandFrame>& hands, const PoseTracks& tracks,
                                              const std::vector<Eigen::AlignedBox3d>& part_bounds, const Camera& camera,
                                              const HandFusionOptions& o) {
  const int parts = static_cast<int>(tracks.object_ids.size());
  std::vector<std::vector<bool>> contact(parts, std::vector<bool>(tracks.frames, false));
  for (const auto& hf : hands) {
    if (hf.frame >= tracks.frames) continue;
    for (size_t h = 0; h < hf.hands.size(); ++h) {
      if (hf.hands[h].contact != HandContact::Portable) continue;
      const int box = contact_object(hf, h);
      if (box < 0) continue;
      // Best overlap among parts seen lately; else the nearest part last seen long ago.
      const cv::Rect2d& ob = hf.objects[box].box;
      int best = -1, nearest = -1;
      double best_iou = o.min_overlap, best_distance = 1.5 * std::hypot(ob.width, ob.height);
      for (int k = 0; k < parts; ++k) {
        int age = 0;
        const auto pb = projected_box(tracks, k, hf.frame, part_bounds[k], camera, age);
        if (!pb) continue;
        if (age <= 5) {
          const double v = iou(*pb, ob);
          if (v > best_iou) best_iou = v, best = k;
        } else {
          const double d = std::hypot(pb->x + pb->width / 2 - ob.x - ob.width / 2, pb->y + pb->height / 2 - ob.y - ob.height / 2);
          if (d < best_distance) best_distance = d, nearest = k;
        }
      }
      if (best < 0) best = nearest;
      if (best >= 0) contact[best][hf.frame] = true;
    }
  }
  std::vector<HandContactRun> runs;
  for (int k = 0; k < parts; ++k) {
    int f = 0;
    while (f < tracks.frames) {
      if (!contact[k][f]) {
        ++f;
        continue;
      }
      HandContactRun r{k, f, f};
      for (int g = f + 1; g < tracks.frames && g - r.last <= o.max_gap + 1; ++g)
        if (contact[k][g]) r.last = g;
      if (r.last - r.first + 1 >= o.min_length) runs.push_back(r);
      f = r.last + 1;
    }
  }
  std::sort(runs.begin(), runs.end(), [](auto& a, auto& b) { return a.first < b.first; });
  return runs;
}

void fuse_hand_contacts(ContactAnalysis& contacts, const std::vector<HandContactRun>& runs, const PoseTracks& tracks,
                        const HandFusionOptions& o) {
  std::vector<bool> used(runs.size(), false);
  std::vector<MotionInterval> carries;
  for (const MotionInterval& c : contacts.carries) {
    std::vector<size_t> mine;  // runs of this part within the carry (sorted by first frame)
    for (size_t r = 0; r < runs.size(); ++r)
      if (runs[r].object == c.object && overlaps(c.start - o.max_shift, c.end + o.max_shift, runs[r].first, runs[r].last + 1))
        mine.push_back(r);
    if (mine.empty()) {
      carries.push_back(c);
      continue;
    }
    // One carry per contact run: the hand let go and took the part again while it was hidden.
    for (size_t i = 0; i < mine.size(); ++i) {
      const HandContactRun& run = runs[mine[i]];
      used[mine[i]] = true;
      MotionInterval m = c;
      const int grasp = run.first, release = run.last + 1;
      if (i > 0 || std::abs(c.start - grasp) <= o.max_shift) {
        m.start_confidence = i == 0 ? std::max(c.start_confidence, std::abs(c.start - grasp) <= 2 ? 0.95 : 0.7) : 0.7;
        m.start = grasp;
      }
      if (i + 1 < mine.size() || std::abs(c.end - release) <= o.max_shift) {
        m.end_confidence = i + 1 == mine.size() ? std::max(c.end_confidence, std::abs(c.end - release) <= 2 ? 0.95 : 0.7) : 0.7;
        m.end = std::min(release, tracks.frames - 1);
      }
      if (m.end > m.start) carries.push_back(m);
    }
  }
  // Contacts with no carry: a carry the poses did not show, when the part was mostly hidden
  // and the hand was free.
  for (size_t r = 0; r < runs.size(); ++r) {
    if (used[r]) continue;
    const HandContactRun& run = runs[r];
    const int grasp = run.first, release = run.last + 1;
    int seen = 0;
    for (int f = grasp; f <= run.last; ++f) seen += tracks.samples[run.object][f].valid;
    const bool hidden = seen * 2 < release - grasp;
    const bool free = std::none_of(carries.begin(), carries.end(),
                                   [&](const MotionInterval& c) { return overlaps(c.start, c.end, grasp, release); });
    if (!hidden || !free || !tracks.planning[run.object]) continue;
    MotionInterval m;
    m.object = run.object;
    m.start = grasp;
    m.end = std::min(release, tracks.frames - 1);
    m.start_confidence = m.end_confidence = 0.6;
    carries.push_back(m);
  }
  std::sort(carries.begin(), carries.end(), [](auto& a, auto& b) { return a.start < b.start; });
  contacts.carries = carries;
}

}  // namespace demoplan::perception
