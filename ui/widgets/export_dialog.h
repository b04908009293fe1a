#pragma once
// Export: pick the controller's format (from the registry of program writers), see the program
// text (Program tab) and each joint's motion against its limits (Joints tab), its duration and
// the limits it keeps, and save it. The export job times the path within
// the robot's joint limits and checks it independently in memory; only Save writes files.
#include <QDialog>

#include "ui/document/document.h"
#include "ui/document/program_export.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPlainTextEdit;
class QPushButton;
class QSpinBox;
class QTabWidget;

namespace demoplan::ui {

class JointPlotView;

class ExportDialog : public QDialog {
  Q_OBJECT
public:
  ExportDialog(Document* doc, bool interactive, QWidget* parent = nullptr);
  QComboBox* formatBox() const { return format_; }
  QPlainTextEdit* preview() const { return preview_; }
  QLabel* summary() const { return summary_; }
  QTabWidget* tabs() const { return tabs_; }
  JointPlotView* jointPlot() const { return joints_; }
  const ProgramExport& last() const { return last_; }
  // Writes the program to `file` (asks where when empty and interactive); true when written.
  bool saveTo(const QString& file = QString());
  // Runs the export job in memory and shows the program; writes nothing.
  void refreshPreview();

private:
  ExportSettings settings(const std::string& file) const;
  std::string defaultFileName() const;  // the format's name for the project's file
  Document* doc_;
  bool interactive_;
  QComboBox* format_;
  QDoubleSpinBox* velocity_;
  QDoubleSpinBox* acceleration_;
  QDoubleSpinBox* rate_;
  QSpinBox* output_;
  QLabel* summary_;
  QTabWidget* tabs_;
  QPlainTextEdit* preview_;
  JointPlotView* joints_;
  QPushButton* save_;
  ProgramExport last_;
};

}  // namespace demoplan::ui
