#include "perception/camera/marker_board.h"

#include "perception/markers/marker_dictionary.h"

namespace demoplan::perception {

cv::Ptr<cv::aruco::GridBoard> MarkerBoard::make() const {
  return cv::aruco::GridBoard::create(markers_x, markers_y, static_cast<float>(marker_length),
                                      static_cast<float>(marker_separation), marker_dictionary(dictionary),
                                      first_id);
}

}  // namespace demoplan::perception
