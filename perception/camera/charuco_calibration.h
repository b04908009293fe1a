#pragma once
// A camera's intrinsics (pinhole + OpenCV distortion k1 k2 p1 p2 k3) from a video, or a folder of
// images, of a ChArUco board (charuco_board.h) shown to the camera in many poses.
//
// Candidate views: at most max_views frames spread evenly over the video (every image of a
// folder, up to max_views). Each is rejected, with its reason, when
//   - "board not seen": fewer than min_corners chessboard corners found, or all on one line;
//   - "blurred": its sharpness is below blur_ratio times the median sharpness of the views that
//     show the board. Sharpness is the mean square of the image's second derivative over the
//     board's region (the hull of its corners) in the direction where it is smallest (a motion
//     blur smooths only the edges across its direction: the Laplacian, summing both, would miss
//     half of it), divided by the region's intensity variance (so it does not depend on lighting
//     or print contrast) and multiplied by the side of a square in pixels (the energy per pixel
//     falls as the squares grow, for the same blur);
//   - "duplicate of frame N": it shows the same corners as an accepted view N, none moved by more
//     than duplicate_px on average (the board, or the camera, did not move between them);
//   - "reprojection error": after a first calibration its error is above outlier_ratio times the
//     median and above min_outlier_px; the camera is then calibrated again without it.
// Too few views left (min_views) is bad input, as is a video where no view shows the board.
#include <atomic>
#include <functional>
#include <string>
#include <vector>

#include "perception/camera/camera_model.h"
#include "perception/camera/charuco_board.h"

namespace demoplan::perception {

struct CharucoCalibrationOptions {
  int max_views = 60;            // candidate frames of a video, spread evenly
  int min_corners = 8;           // chessboard corners a view needs
  int min_views = 6;             // accepted views a calibration needs
  double blur_ratio = 0.2;       // of the median sharpness
  double duplicate_px = 0.01;    // of the image's diagonal: mean corner motion of a duplicate
  double outlier_ratio = 3.0;    // of the median per-view error
  double min_outlier_px = 1.0;   // a view with a smaller error is never an outlier
  std::function<void(int done, int total)> progress;  // candidate views examined
  const std::atomic<bool>* cancel = nullptr;           // checked between views
};

struct CalibrationView {
  int frame = 0;         // frame index in the video, or index of the image in the folder (sorted by name)
  std::string image;     // the image's file name, for a folder
  int corners = 0;       // chessboard corners found
  double sharpness = 0;  // see above; 0 when the board was not seen
  bool used = false;
  std::string rejected;  // why not used
  double error_px = 0;   // RMS reprojection error of a used view
};

struct CharucoCalibration {
  Camera camera;          // intrinsics, distortion, image size; no pose
  double rms_px = 0;      // over all corners of the used views
  std::vector<CalibrationView> views;  // every candidate, in frame order
  int views_used = 0, views_rejected = 0;
  int frames = 0;         // frames (or images) in the source
  double seconds = 0;
  bool cancelled = false;  // then camera and rms_px are not set
};

// `source`: a video file or a folder of images (png, jpg, jpeg, bmp, tif, tiff). Throws InputError
// naming `source` (and the frame or image) when it cannot be read, when no view shows the board,
// or when too few usable views remain.
CharucoCalibration calibrate_charuco(const std::string& source, const CharucoBoard& board,
                                     const CharucoCalibrationOptions& options = {});

}  // namespace demoplan::perception
