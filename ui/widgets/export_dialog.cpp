#include "ui/widgets/export_dialog.h"

#include <QApplication>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFontDatabase>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QScrollArea>
#include <QSpinBox>
#include <QTabWidget>
#include <QVBoxLayout>

#include "core/error.h"
#include "core/export/program_writers.h"
#include "ui/widgets/joint_plot_view.h"
#include "ui/widgets/style.h"

namespace demoplan::ui {

ExportDialog::ExportDialog(Document* doc, bool interactive, QWidget* parent)
    : QDialog(parent), doc_(doc), interactive_(interactive) {
  setWindowTitle(tr("Export the robot program"));
  resize(900, 640);
  auto* layout = new QVBoxLayout(this);
  auto* top = new QHBoxLayout;
  auto* form = new QFormLayout;
  format_ = new QComboBox(this);
  for (const ProgramWriter* w : program_writers())
    format_->addItem(QString::fromStdString(w->format().label), QString::fromStdString(w->id()));
  format_->setToolTip(tr("The controller's language. Formats that do not fit the robot (URScript needs a 6-axis "
                         "arm) say so below."));
  // A sensible first choice for the robot.
  const std::string robot = doc_->hasProject() ? doc_->scene().robot.name : "";
  const QString preferred = robot == "ur5" ? QStringLiteral("urscript") : robot == "panda" ? QStringLiteral("franka")
                                                                                            : QStringLiteral("sunrise");
  format_->setCurrentIndex(std::max(0, format_->findData(preferred)));
  form->addRow(tr("Controller"), format_);
  velocity_ = new QDoubleSpinBox(this);
  velocity_->setRange(1, 100);
  velocity_->setValue(100);
  velocity_->setSuffix(QStringLiteral(" %"));
  velocity_->setToolTip(tr("Fraction of the joint velocity limits the program may use"));
  form->addRow(tr("Velocity"), velocity_);
  acceleration_ = new QDoubleSpinBox(this);
  acceleration_->setRange(1, 100);
  acceleration_->setValue(100);
  acceleration_->setSuffix(QStringLiteral(" %"));
  acceleration_->setToolTip(tr("Fraction of the acceleration and jerk limits the program may use"));
  form->addRow(tr("Acceleration"), acceleration_);
  rate_ = new QDoubleSpinBox(this);
  rate_->setRange(0, 2000);
  rate_->setDecimals(0);
  rate_->setSuffix(QStringLiteral(" Hz"));
  rate_->setSpecialValueText(tr("format default"));
  rate_->setToolTip(tr("Sample rate of streamed formats, at which the trajectory is also checked. Defaults: %1")
                        .arg(QString::fromStdString(default_rates_text())));
  form->addRow(tr("Sample rate"), rate_);
  output_ = new QSpinBox(this);
  output_->setRange(-1, 64);
  output_->setValue(-1);
  output_->setSpecialValueText(tr("format default"));
  output_->setToolTip(tr("Digital output that closes the gripper (UR default 0, KRL 1)"));
  form->addRow(tr("Gripper output"), output_);
  top->addLayout(form, 2);
  summary_ = new QLabel(this);
  summary_->setWordWrap(true);
  summary_->setTextFormat(Qt::RichText);
  summary_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
  summary_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  top->addWidget(summary_, 3);
  layout->addLayout(top);
  preview_ = new QPlainTextEdit(this);
  preview_->setReadOnly(true);
  preview_->setLineWrapMode(QPlainTextEdit::NoWrap);
  preview_->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
  // The program as text, and the motion it commands as plots against the limits.
  tabs_ = new QTabWidget(this);
  tabs_->addTab(preview_, tr("Program"));
  joints_ = new JointPlotView;
  auto* scroll = new QScrollArea;
  scroll->setWidget(joints_);
  scroll->setWidgetResizable(true);
  scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  tabs_->addTab(scroll, tr("Joints"));
  tabs_->setTabToolTip(1, tr("Each joint's position, velocity and acceleration over time, the limits the program "
                             "keeps (dashed) and where the robot rests (shaded)"));
  layout->addWidget(tabs_, 1);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
  save_ = buttons->addButton(tr("Save…"), QDialogButtonBox::AcceptRole);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  connect(save_, &QPushButton::clicked, this, [this] {
    if (saveTo()) accept();
  });
  layout->addWidget(buttons);
  connect(format_, &QComboBox::currentIndexChanged, this, &ExportDialog::refreshPreview);
  for (auto* s : {velocity_, acceleration_, rate_}) connect(s, &QDoubleSpinBox::valueChanged, this, &ExportDialog::refreshPreview);
  connect(output_, &QSpinBox::valueChanged, this, &ExportDialog::refreshPreview);
  refreshPreview();
}

ExportSettings ExportDialog::settings(const std::string& file) const {
  ExportSettings s;
  s.format = format_->currentData().toString().toStdString();
  s.velocity_scale = velocity_->value() / 100.0;
  s.acceleration_scale = acceleration_->value() / 100.0;
  s.rate = rate_->value();
  s.gripper_output = output_->value();
  s.file = file;
  // Errors about the path name its file; without one, the header says which plan it is.
  const PlanResultData* r = doc_->planning()->result();
  if (r && !r->summary.path.empty()) s.source = r->summary.path;
  else if (r && r->path) s.source = r->path->task + " " + r->path->robot + " pose " + std::to_string(r->path->robot_pose);
  return s;
}

std::string ExportDialog::defaultFileName() const {
  const std::string stem =
      QFileInfo(doc_->filePath().isEmpty() ? QStringLiteral("job") : doc_->filePath()).completeBaseName().toStdString();
  const ProgramWriter* w = find_program_writer(format_->currentData().toString().toStdString());
  return w ? w->file_name(stem) : stem;
}

void ExportDialog::refreshPreview() {
  const PlanResultData* r = doc_->planning()->result();
  if (!doc_->hasProject() || !r || !r->path) {
    summary_->setText(tr("No planned path: plan first (F5)."));
    preview_->clear();
    joints_->setMessage(tr("No planned path: plan first (F5)."));
    save_->setEnabled(false);
    return;
  }
  QApplication::setOverrideCursor(Qt::WaitCursor);
  last_ = run_program_export(doc_->scene(), *r->path, doc_->dataDir(), settings(defaultFileName()));
  QApplication::restoreOverrideCursor();
  QString html;
  if (!last_.ok) {
    html = tr("<span style='color:%1'><b>Cannot export:</b></span> %2")
               .arg(kErrorColor.name(), QString::fromStdString(last_.error).toHtmlEscaped());
    preview_->setPlainText(tr("(nothing to show: %1)").arg(QString::fromStdString(last_.error)));
  } else {
    html = tr("<b>Duration %1 s</b> (stopping at every waypoint would take %2 s)<br>"
              "Peak velocity %3% and acceleration %4% of the limits · independent check: <b>%5</b>")
               .arg(last_.duration_s, 0, 'f', 2)
               .arg(last_.trapezoid_duration_s, 0, 'f', 2)
               .arg(last_.peak_velocity_ratio * 100, 0, 'f', 0)
               .arg(last_.peak_acceleration_ratio * 100, 0, 'f', 0)
               .arg(last_.check_ok ? tr("ok") : tr("failed"));
    html += tr("<br>%n corner(s) passed without stopping, each checked collision-free", nullptr, int(last_.blends));
    if (last_.rests_added > 0)
      html += tr("; the robot stops at %n more where passing would touch the scene", nullptr, int(last_.rests_added));
    preview_->setPlainText(QString::fromStdString(program_preview_text(last_.files)));
  }
  // The motion also when its check failed: the plots show where it leaves the limits.
  if (!last_.trajectory.samples.empty()) {
    std::vector<QString> units;
    for (const Joint* j : doc_->scene().robot.model.configuration_joints()) {
      if (j->q_index < 0) continue;
      if (units.size() <= static_cast<size_t>(j->q_index)) units.resize(static_cast<size_t>(j->q_index) + 1);
      units[static_cast<size_t>(j->q_index)] = j->type == JointType::Prismatic ? QStringLiteral("m") : QStringLiteral("rad");
    }
    joints_->setTrajectory(last_.trajectory, units);
  } else {
    joints_->setMessage(QString::fromStdString(last_.error));
  }
  if (!last_.limits.empty()) {
    html += tr("<br><small>Limits used:");
    for (const auto& l : last_.limits) html += QStringLiteral("<br>&nbsp;&nbsp;") + QString::fromStdString(l).toHtmlEscaped();
    html += QStringLiteral("</small>");
  }
  for (const auto& w : last_.warnings)
    html += QStringLiteral("<br><span style='color:%1'>%2</span>").arg(kWarningColor.darker(120).name(), QString::fromStdString(w).toHtmlEscaped());
  summary_->setText(html);
  save_->setEnabled(last_.ok);
}

bool ExportDialog::saveTo(const QString& file_in) {
  const PlanResultData* r = doc_->planning()->result();
  if (!r || !r->path) return false;
  QString file = file_in;
  if (file.isEmpty()) {
    if (!interactive_) return false;
    const QString dir = doc_->filePath().isEmpty() ? QDir::homePath() : QFileInfo(doc_->filePath()).absolutePath();
    file = QFileDialog::getSaveFileName(this, tr("Save the program"),
                                        dir + QLatin1Char('/') + QString::fromStdString(defaultFileName()));
    if (file.isEmpty()) return false;
  }
  // Again for this file: its name is the program's (KRL module, Sunrise class, URScript function).
  ProgramExport out = run_program_export(doc_->scene(), *r->path, doc_->dataDir(), settings(file.toStdString()));
  if (out.ok) {
    try {
      write_program_files(out.files);
    } catch (const InputError& e) {
      out.ok = false;
      out.error = e.what();
    }
  }
  last_ = out;
  if (!out.ok) {
    if (interactive_) QMessageBox::critical(this, tr("Cannot export"), QString::fromStdString(out.error));
    summary_->setText(tr("<span style='color:%1'><b>Cannot export:</b></span> %2")
                          .arg(kErrorColor.name(), QString::fromStdString(out.error).toHtmlEscaped()));
    return false;
  }
  doc_->steps()->markExported(QString::fromStdString(out.files.empty() ? file.toStdString() : out.files.front().name));
  return true;
}

}  // namespace demoplan::ui
