#pragma once
// How each of the operator's five steps stands (UX.md), derived from the project and kept up to
// date by the changes that can alter it: an edit, a file, a plan's start or end, an export.
// Planner progress does not touch it, and the Poses step's graph is built only when the
// demonstration changes, so the GUI thread builds no graph while the planner runs.
#include <QObject>
#include <QString>
#include <array>

namespace demoplan::ui {

class Document;

// Events the detector is less sure of than this are flagged for the operator to check.
inline constexpr double kLowConfidence = 0.5;

enum class Step { Video = 0, Events, Poses, Plan, Export };
enum class StepStatus { None, Ok, Warning, Error, Busy };
struct StepState {
  StepStatus status = StepStatus::None;
  QString message;  // one line: what is wrong and what to do next
};

class StepStatusModel : public QObject {
  Q_OBJECT
public:
  // Listens to `doc` (and its media, planning and event detection).
  explicit StepStatusModel(Document* doc);

  const StepState& state(Step step) const { return states_[static_cast<size_t>(step)]; }
  void markExported(const QString& file);
  // How many times the Poses step built the constraint graph (for tests).
  int graphBuilds() const { return graph_builds_; }

signals:
  void changed();

private:
  void refresh();                 // every step but Poses
  void refreshPoses();            // after an edit: builds the constraint graph
  StepState video() const;
  StepState events() const;
  StepState plan() const;
  StepState exported() const;

  Document* doc_;
  std::array<StepState, 5> states_;
  QString exported_to_;
  int graph_builds_ = 0;
};

}  // namespace demoplan::ui
