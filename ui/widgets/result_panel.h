#pragma once
// The result: the validator's verdict and metrics, the path's waypoints with their actions
// (move, approach, grasp, carry, release, retreat), and playback of the robot and the parts
// along the path (play, pause, scrub, speed). Selecting a waypoint jumps there.
#include <QWidget>

#include "ui/document/document.h"

class QComboBox;
class QLabel;
class QPushButton;
class QSlider;
class QTableWidget;
class QTimer;

namespace demoplan::ui {

// What the robot does on the way from waypoint k to k+1 (or at k for grasp/release).
QStringList waypointActions(const Path& path, const std::vector<std::string>& state_names = {});

class ResultPanel : public QWidget {
  Q_OBJECT
public:
  explicit ResultPanel(Document* doc, QWidget* parent = nullptr);
  QLabel* verdictLabel() const { return verdict_; }
  QTableWidget* waypointTable() const { return table_; }
  QSlider* slider() const { return slider_; }
  QPushButton* playButton() const { return play_; }
  QPushButton* exportButton() const { return export_; }
  bool isPlaying() const;

public slots:
  void togglePlay();
  void pause();

signals:
  void exportRequested();

private:
  void refresh();
  void onTick();
  void syncSlider();

  Document* doc_;
  QLabel* verdict_;
  QLabel* metrics_;
  QTableWidget* table_;
  QPushButton* play_;
  QSlider* slider_;
  QComboBox* speed_;
  QLabel* time_;
  QPushButton* export_;
  QTimer* timer_;
  qint64 last_tick_ms_ = 0;
};

}  // namespace demoplan::ui
