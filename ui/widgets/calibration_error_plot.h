#pragma once
// Each view of a camera calibration as a bar: its RMS reprojection error in pixels, in frame
// order, with the overall RMS as a line; a view left out is a grey tick whose tooltip says why
// (board not seen, blurred, a duplicate, an outlier). An operator sees at a glance whether a few
// views spoil the calibration and where in the video they are.
#include <QWidget>
#include <vector>

#include "perception/camera/charuco_calibration.h"

namespace demoplan::ui {

class CalibrationErrorPlot : public QWidget {
  Q_OBJECT
public:
  explicit CalibrationErrorPlot(QWidget* parent = nullptr);
  void setCalibration(const std::vector<perception::CalibrationView>& views, double rms_px);
  void clear();
  // The view under a widget x coordinate, -1 for none (for the tooltip).
  int viewAt(double x) const;
  QSize sizeHint() const override { return {480, 160}; }

protected:
  void paintEvent(QPaintEvent*) override;
  bool event(QEvent* e) override;

private:
  QRectF plotArea() const;
  double maxError() const;

  std::vector<perception::CalibrationView> views_;
  double rms_px_ = 0.0;
};

}  // namespace demoplan::ui
