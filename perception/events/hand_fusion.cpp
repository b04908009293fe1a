#include "perception/events/hand_fusion.h"

#include <algorithm>
#include <cmath>

namespace demoplan::perception {

namespace {

// The part's pixel box at a frame, from its nearest sample within 5 frames.
std::optional<cv::Rect2d> projected_box(const PoseTracks& tracks, int row, int frame, const Eigen::AlignedBox3d& bounds,
                                        const Camera& camera) {
  const auto& s = tracks.samples[row];
  const Pose camera_T_world = camera.world_T_camera->inverse();
  for (int d = 0; d <= 5; ++d)
    for (int f : {frame - d, frame + d}) {
      if (f < 0 || f >= tracks.frames || !s[f].valid) continue;
      double x0 = 1e18, y0 = 1e18, x1 = -1e18, y1 = -1e18;
      for (int c = 0; c < 8; ++c) {
        const Eigen::Vector3d p = camera_T_world * (s[f].pose * bounds.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c)));
        if (p.z() <= 0.05) return std::nullopt;
        const cv::Point2d q = camera.project(p);
        x0 = std::min(x0, q.x), y0 = std::min(y0, q.y), x1 = std::max(x1, q.x), y1 = std::max(y1, q.y);
      }
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
      int best = -1;
      double best_iou = o.min_overlap;
      for (int k = 0; k < parts; ++k)
        if (const auto pb = projected_box(tracks, k, hf.frame, part_bounds[k], camera)) {
          const double v = iou(*pb, hf.objects[box].box);
          if (v > best_iou) best_iou = v, best = k;
        }
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
  for (const auto& run : runs) {
    const int grasp = run.first, release = run.last + 1;
    auto it = std::find_if(contacts.carries.begin(), contacts.carries.end(), [&](const MotionInterval& c) {
      return c.object == run.object && overlaps(c.start - o.max_shift, c.end + o.max_shift, grasp, release);
    });
    if (it != contacts.carries.end()) {
      if (std::abs(it->start - grasp) <= o.max_shift) {
        it->start_confidence = std::max(it->start_confidence, std::abs(it->start - grasp) <= 2 ? 0.95 : 0.7);
        it->start = grasp;
      }
      if (std::abs(it->end - release) <= o.max_shift) {
        it->end_confidence = std::max(it->end_confidence, std::abs(it->end - release) <= 2 ? 0.95 : 0.7);
        it->end = release;
      }
      continue;
    }
    // A carry the poses did not show: only when the part was mostly hidden and the hand was free.
    int seen = 0;
    for (int f = grasp; f <= run.last; ++f) seen += tracks.samples[run.object][f].valid;
    const bool hidden = seen * 2 < release - grasp;
    const bool free = std::none_of(contacts.carries.begin(), contacts.carries.end(),
                                   [&](const MotionInterval& c) { return overlaps(c.start, c.end, grasp, release); });
    if (!hidden || !free || !tracks.planning[run.object]) continue;
    MotionInterval m;
    m.object = run.object;
    m.start = grasp;
    m.end = std::min(release, tracks.frames - 1);
    m.start_confidence = m.end_confidence = 0.6;
    contacts.carries.push_back(m);
  }
  std::sort(contacts.carries.begin(), contacts.carries.end(), [](auto& a, auto& b) { return a.start < b.start; });
}

}  // namespace demoplan::perception
