#pragma once
// The planner panel: its parameters with safe defaults and tooltips, Plan and Cancel, a progress
// bar with the elapsed time, iterations, trees and nodes, a table counting nodes per state (a
// state nobody reaches stands out), and the failure message naming the transitions never sampled.
#include <QWidget>
#include <memory>

#include "ui/document/document.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace demoplan::ui {

class PlannerPanel : public QWidget {
  Q_OBJECT
public:
  explicit PlannerPanel(Document* doc, QWidget* parent = nullptr);
  QPushButton* planButton() const { return plan_; }
  QPushButton* cancelButton() const { return cancel_; }
  QProgressBar* progressBar() const { return progress_; }
  QTableWidget* stateTable() const { return states_; }
  QLabel* statsLabel() const { return stats_; }
  QLabel* messageLabel() const { return message_; }
  QComboBox* plannerBox() const { return planner_; }
  QSpinBox* seedBox() const { return seed_; }
  QDoubleSpinBox* timeLimitBox() const { return time_limit_; }

  void plan();    // what the Plan button does
  void cancel();  // what the Cancel button does

private:
  void loadSettings();
  void storeSettings();
  void setRunning(bool running);
  void showStates(const std::vector<std::string>& names, const std::vector<size_t>& nodes);
  void onProgress(const PlanSnapshot& s);
  void onResult();

  Document* doc_;
  QComboBox* planner_;
  QSpinBox* seed_;
  QDoubleSpinBox* time_limit_;
  QSpinBox* max_iterations_;
  QSpinBox* regrasp_after_;
  QDoubleSpinBox* eta_;
  QDoubleSpinBox* step_;
  QDoubleSpinBox* resolution_;
  QCheckBox* shortcut_;
  QDoubleSpinBox* shortcut_time_;
  QPushButton* plan_;
  QPushButton* cancel_;
  QPushButton* defaults_;
  QProgressBar* progress_;
  QLabel* stats_;
  QLabel* message_;
  QTableWidget* states_;
  std::vector<std::string> state_names_;
  bool loading_ = false;
};

}  // namespace demoplan::ui
