#pragma once
// Markers for synthetic parts: one square ArUco marker centred on each face of the part's
// bounding box (6 per part, ids first_id .. first_id + 5), and their printed images.
#include <set>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "core/cell/cell.h"
#include "perception/markers/marker_scene.h"

namespace demoplan::perception {

struct MarkerLayoutOptions {
  double max_size = 0.10;       // m, black square side
  double face_fraction = 0.72;  // of the face's shorter side (the white margin must fit too)
  double standoff = 0.001;      // m, in front of the box face
};

inline constexpr int kBoxFaceMarkers = 6;  // box_face_markers: one per face
std::vector<ObjectMarker> box_face_markers(const Eigen::AlignedBox3d& bounds, int first_id,
                                           const MarkerLayoutOptions& options = {});

// Marker ids, each handed out once: blocks of consecutive ids that no marker holds yet.
class MarkerIds {
public:
  explicit MarkerIds(std::set<int> used = {}) : used_(std::move(used)) {}
  int take(int count);  // the first id of the block
private:
  std::set<int> used_;
  int next_ = 0;
};

// The markers on a cell's parts, as extraction reads them: a part's own markers from the cell
// where it has some, else one on each face of its bounding box (`bounds`, in the part frame) with
// ids that no cell marker uses. `ids` holds the ids in use afterwards (for a board's markers).
std::vector<MarkedObject> cell_part_markers(const Cell& cell, const std::vector<std::string>& part_ids,
                                            const std::vector<Eigen::AlignedBox3d>& bounds, MarkerIds* ids = nullptr);

// The printed marker: black border and bits (cells of `cell_pixels`) plus a white margin one
// cell wide all around, 8-bit grey.
cv::Mat marker_image(const std::string& dictionary, int id, int cell_pixels = 16);
// Side of the printed square, white margin included, for a marker of black side `size`.
double printed_marker_side(const std::string& dictionary, double size);

}  // namespace demoplan::perception
