#pragma once
// The Placement panel: where should the robot stand for this task? The region (x, y and yaw
// ranges, around the robot's base until the operator sets one), how many candidates, seeds and
// the time per plan; Search and Cancel with a progress bar; the heat map filling in as the
// background search reports; the chosen candidate's numbers and "Stand the robot here", which
// moves the robot (one undo step) and plans again.
#include <QWidget>

#include "ui/document/document.h"

class QDoubleSpinBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QSpinBox;

namespace demoplan::ui {

class PlacementMapView;

class PlacementPanel : public QWidget {
  Q_OBJECT
public:
  explicit PlacementPanel(Document* doc, QWidget* parent = nullptr);
  PlacementMapView* mapView() const { return map_; }
  QPushButton* searchButton() const { return search_; }
  QPushButton* cancelButton() const { return cancel_; }
  QPushButton* standButton() const { return stand_; }
  QProgressBar* progressBar() const { return progress_; }
  QLabel* messageLabel() const { return message_; }
  QSpinBox* samplesBox() const { return samples_; }
  QSpinBox* seedsBox() const { return seeds_; }
  QDoubleSpinBox* timeLimitBox() const { return time_limit_; }

  void search();  // what Search does
  void cancel();  // what Cancel does
  // Stands the robot at the chosen candidate and plans: what "Stand the robot here" does.
  void standAtChosen();

private:
  void loadSettings();
  void storeSettings();
  void setRunning(bool running);
  void refreshSummary();
  void refreshChosen();

  Document* doc_;
  QDoubleSpinBox *x0_, *x1_, *y0_, *y1_, *yaw0_, *yaw1_;
  QSpinBox* samples_;
  QSpinBox* seeds_;
  QDoubleSpinBox* time_limit_;
  QPushButton* search_;
  QPushButton* cancel_;
  QProgressBar* progress_;
  QLabel* summary_;
  PlacementMapView* map_;
  QLabel* chosen_;
  QPushButton* stand_;
  QLabel* message_;
};

}  // namespace demoplan::ui
