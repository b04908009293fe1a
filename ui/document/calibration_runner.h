#pragma once
// Calibrates the camera from a video (or a folder of images) of a ChArUco board
// (perception's calibrate_charuco) on a background thread, with progress and cancel, as the
// extraction runs.
#include <string>

#include "perception/camera/charuco_calibration.h"
#include "ui/document/background_job.h"

namespace demoplan::ui {

struct CalibrationOutcome {
  bool ok = false;
  std::string error;  // one line naming the file and the frame or field
  perception::CharucoCalibration calibration;
};

class CalibrationRunner : public BackgroundJob {
  Q_OBJECT
public:
  using BackgroundJob::BackgroundJob;
  // `source`: a video or a folder of images; `board`: a demoplan-charuco-board file.
  bool start(const std::string& source, const std::string& board);

signals:
  void progress(int done, int total);
  void finished(const CalibrationOutcome& outcome);
};

}  // namespace demoplan::ui
