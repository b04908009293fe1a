#pragma once
// Calibrate Camera: the intrinsics from a short video (or a folder of images) of a printed
// ChArUco board. The operator picks the recording and the board file, the calibration runs in
// the background (progress bar, Cancel), then shows its RMS, focal lengths and principal point
// and a plot of every view's error (views left out marked with why). Use This Camera writes the
// camera file and sets it on the project; the camera's pose in the cell and its board are kept
// from the project's camera, as recalibrating the lens does not move the camera.
#include <QDialog>
#include <optional>

#include "perception/camera/charuco_calibration.h"
#include "ui/document/calibration_runner.h"
#include "ui/document/document.h"

class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;

namespace demoplan::ui {

class CalibrationErrorPlot;

class CalibrationDialog : public QDialog {
  Q_OBJECT
public:
  explicit CalibrationDialog(Document* doc, QWidget* parent = nullptr);
  void setSource(const QString& video_or_folder);
  void setBoard(const QString& board_file);
  bool start();  // false with the reason shown
  void cancel();
  bool isRunning() const { return runner_.isRunning(); }
  const perception::CharucoCalibration* result() const { return result_ ? &*result_ : nullptr; }
  // Writes the calibrated camera to `camera_file` (pose and board kept from the project's
  // camera) and sets it on the project; false with the reason shown.
  bool useCamera(const QString& camera_file);

  QProgressBar* progressBar() const { return progress_; }
  QLabel* summaryLabel() const { return summary_; }
  CalibrationErrorPlot* plot() const { return plot_; }
  QPushButton* startButton() const { return start_; }
  QPushButton* useButton() const { return use_; }

private:
  void onFinished(const CalibrationOutcome& outcome);
  void showError(const QString& text);
  void chooseUseFile();

  Document* doc_;
  CalibrationRunner runner_;
  QLineEdit* source_;
  QLineEdit* board_;
  QPushButton* start_;
  QPushButton* cancel_;
  QPushButton* use_;
  QProgressBar* progress_;
  QLabel* summary_;
  CalibrationErrorPlot* plot_;
  std::optional<perception::CharucoCalibration> result_;
};

}  // namespace demoplan::ui
