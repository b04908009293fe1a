#include "perception/synthetic/marker_layout.h"

#include <algorithm>

#include "core/cell/part_markers.h"
#include "perception/markers/marker_dictionary.h"

namespace demoplan::perception {

namespace {
int cells_with_border(const std::string& dictionary) { return marker_dictionary(dictionary)->markerSize + 2; }
}  // namespace

std::vector<ObjectMarker> box_face_markers(const Eigen::AlignedBox3d& bounds, int first_id,
                                           const MarkerLayoutOptions& options) {
  const Eigen::Vector3d c = bounds.center(), h = bounds.sizes() / 2;
  std::vector<ObjectMarker> out;
  int id = first_id;
  for (int axis = 0; axis < 3; ++axis)
    for (int sign : {+1, -1}) {
      const Eigen::Vector3d z = sign * Eigen::Vector3d::Unit(axis);
      const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
      ObjectMarker m;
      m.id = id++;
      m.size = std::min(options.max_size, options.face_fraction * 2 * std::min(h[a1], h[a2]));
      // The printed image's "up": +z of the part on its sides, +x on top and bottom.
      m.object_T_marker.linear() = marker_frame_on_face(z);
      m.object_T_marker.translation() = c + z * (h[axis] + options.standoff);
      out.push_back(m);
    }
  return out;
}

int MarkerIds::take(int count) {
  for (;; ++next_) {
    bool clear = true;
    for (int k = 0; k < count && clear; ++k) clear = !used_.count(next_ + k);
    if (clear) break;
  }
  const int first = next_;
  for (int k = 0; k < count; ++k) used_.insert(next_++);
  return first;
}

std::vector<MarkedObject> cell_part_markers(const Cell& cell, const std::vector<std::string>& part_ids,
                                            const std::vector<Eigen::AlignedBox3d>& bounds, MarkerIds* ids) {
  std::set<int> used;
  for (const auto& p : cell.parts)
    for (const auto& m : p.markers) used.insert(m.id);
  MarkerIds local;
  MarkerIds& free_ids = ids ? *ids : local;
  free_ids = MarkerIds(std::move(used));
  std::vector<MarkedObject> out;
  for (size_t k = 0; k < part_ids.size(); ++k) {
    MarkedObject& o = out.emplace_back();
    o.id = part_ids[k];
    const int c = cell.part_index(part_ids[k]);
    if (c >= 0)
      for (const auto& cm : cell.parts[static_cast<size_t>(c)].markers) o.markers.push_back({cm.id, cm.size, cm.pose});
    if (o.markers.empty()) o.markers = box_face_markers(bounds[k], free_ids.take(kBoxFaceMarkers));
  }
  return out;
}

cv::Mat marker_image(const std::string& dictionary, int id, int cell_pixels) {
  const int cells = cells_with_border(dictionary);
  cv::Mat inner;
  cv::aruco::drawMarker(marker_dictionary(dictionary), id, cells * cell_pixels, inner, 1);
  cv::Mat out(inner.rows + 2 * cell_pixels, inner.cols + 2 * cell_pixels, CV_8U, cv::Scalar(255));
  inner.copyTo(out(cv::Rect(cell_pixels, cell_pixels, inner.cols, inner.rows)));
  return out;
}

double printed_marker_side(const std::string& dictionary, double size) {
  const int cells = cells_with_border(dictionary);
  return size * (cells + 2) / cells;
}

}  // namespace demoplan::perception
