#pragma once
// Per-frame hand-contact detections as the 100DOH hand_object_detector (Shan et al., CVPR
// 2020) produces them, wrapped in a small JSON file (see docs/perception.md):
//   {"format": "demoplan-hand-detections", "version": 1,
//    "frames": [{"frame": 12,
//                "hand_dets": [[x1, y1, x2, y2, score, state, magnitude, dx, dy, lr], ...],
//                "obj_dets":  [[x1, y1, x2, y2, score, ...], ...]}, ...]}
// hand_dets and obj_dets are the detector's two arrays for the frame, row by row (pixels;
// state 0 no contact, 1 self, 2 other person, 3 portable object, 4 stationary object; lr 0
// left, 1 right). A hand in contact points at its object through the offset vector: the
// object box whose centre is nearest to hand centre + magnitude * 10000 * (dx, dy).
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace demoplan::perception {

enum class HandContact { None = 0, Self = 1, OtherPerson = 2, Portable = 3, Stationary = 4 };

struct HandDetection {
  cv::Rect2d box;
  double score = 1.0;
  HandContact contact = HandContact::None;
  double magnitude = 0.0, dx = 0.0, dy = 0.0;
  bool right = true;
};

struct ObjectBox {
  cv::Rect2d box;
  double score = 1.0;
};

struct HandFrame {
  int frame = 0;
  std::vector<HandDetection> hands;
  std::vector<ObjectBox> objects;
};

// Sorted by frame. Throws InputError naming the frame entry and the array for bad rows.
std::vector<HandFrame> load_hand_detections(const std::string& path);
void save_hand_detections(const std::string& path, const std::vector<HandFrame>& frames);

// The object box the hand is in contact with (100DOH's association), -1 when none.
int contact_object(const HandFrame& frame, size_t hand);

}  // namespace demoplan::perception
