#include "perception/importers/hand_detections.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "perception/io/pose_json.h"

namespace demoplan::perception {

namespace {
constexpr const char* kFormat = "demoplan-hand-detections";
constexpr int kVersion = 1;

cv::Rect2d box_of(const JsonField& row) {
  const double x1 = row[0].number(), y1 = row[1].number(), x2 = row[2].number(), y2 = row[3].number();
  if (x2 < x1 || y2 < y1) row.fail("box must be x1, y1, x2, y2 with x2 >= x1 and y2 >= y1");
  return {x1, y1, x2 - x1, y2 - y1};
}
}  // namespace

std::vector<HandFrame> load_hand_detections(const std::string& path) {
  const Json json = read_json_file(path);
  const JsonField root(json, path);
  check_format(root, kFormat, kVersion);
  const JsonField frames = root["frames"];
  std::vector<HandFrame> out;
  for (size_t i = 0; i < frames.size(); ++i) {
    const JsonField f = frames[i];
    HandFrame hf;
    hf.frame = f["frame"].integer();
    if (hf.frame < 0) f["frame"].fail("must be >= 0");
    const JsonField hands = f["hand_dets"];
    for (size_t k = 0; k < hands.size(); ++k) {
      const JsonField row = hands[k];
      if (row.size() < 10) row.fail("a hand row needs 10 numbers: x1, y1, x2, y2, score, state, magnitude, dx, dy, lr");
      HandDetection h;
      h.box = box_of(row);
      h.score = row[4].number();
      const double state = row[5].number();
      if (state < 0 || state > 4 || state != static_cast<int>(state)) row[5].fail("contact state must be 0..4");
      h.contact = static_cast<HandContact>(static_cast<int>(state));
      h.magnitude = row[6].number();
      h.dx = row[7].number();
      h.dy = row[8].number();
      h.right = row[9].number() >= 0.5;
      hf.hands.push_back(h);
    }
    if (f.has("obj_dets")) {
      const JsonField objects = f["obj_dets"];
      for (size_t k = 0; k < objects.size(); ++k) {
        const JsonField row = objects[k];
        if (row.size() < 5) row.fail("an object row needs at least 5 numbers: x1, y1, x2, y2, score");
        hf.objects.push_back({box_of(row), row[4].number()});
      }
    }
    out.push_back(std::move(hf));
  }
  std::stable_sort(out.begin(), out.end(), [](auto& a, auto& b) { return a.frame < b.frame; });
  return out;
}

void save_hand_detections(const std::string& path, const std::vector<HandFrame>& frames) {
  Json list = Json::array();
  for (const auto& f : frames) {
    Json hands = Json::array(), objects = Json::array();
    for (const auto& h : f.hands)
      hands.push_back({h.box.x, h.box.y, h.box.x + h.box.width, h.box.y + h.box.height, h.score,
                       static_cast<int>(h.contact), h.magnitude, h.dx, h.dy, h.right ? 1 : 0});
    for (const auto& o : f.objects)
      objects.push_back({o.box.x, o.box.y, o.box.x + o.box.width, o.box.y + o.box.height, o.score});
    list.push_back({{"frame", f.frame}, {"hand_dets", hands}, {"obj_dets", objects}});
  }
  write_json_file_atomic(path, {{"format", kFormat}, {"version", kVersion}, {"frames", list}}, -1);
}

int contact_object(const HandFrame& f, size_t hand) {
  const HandDetection& h = f.hands.at(hand);
  if (h.contact == HandContact::None || f.objects.empty()) return -1;
  const double px = h.box.x + h.box.width / 2 + h.magnitude * 10000 * h.dx;
  const double py = h.box.y + h.box.height / 2 + h.magnitude * 10000 * h.dy;
  int best = -1;
  double best_d = std::numeric_limits<double>::infinity();
  for (size_t k = 0; k < f.objects.size(); ++k) {
    const auto& b = f.objects[k].box;
    const double d = std::pow(b.x + b.width / 2 - px, 2) + std::pow(b.y + b.height / 2 - py, 2);
    if (d < best_d) best_d = d, best = static_cast<int>(k);
  }
  return best;
}

}  // namespace demoplan::perception
