#include "perception/tracking/placement_witness.h"

namespace demoplan::perception {

void PlacementWitness::place(int frame, const Pose& camera_T_part) {
  *this = PlacementWitness();
  open = true;
  from = frame;
  camera_T_placed = camera_T_part;
}

void PlacementWitness::look(int frame, const cv::Mat& image, const OcclusionMap& map, double placed, double tracked,
                            double clear) {
  if (placed <= clear) last_clear = frame;
  if (placed >= clearest.outliers) return;
  clearest = {frame, image.clone(), map, camera_T_placed, placed};
  tracked_outliers = tracked;
}

bool PlacementWitness::borne_out(double clear, double margin) const {
  return clearest.frame >= 0 && last_clear >= 0 && clearest.outliers <= clear &&
         tracked_outliers >= clearest.outliers + margin;
}

}  // namespace demoplan::perception
