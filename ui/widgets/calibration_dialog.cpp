#include "ui/widgets/calibration_dialog.h"

#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QVBoxLayout>
#include <algorithm>

#include "core/error.h"
#include "perception/camera/camera_model.h"
#include "ui/widgets/calibration_error_plot.h"

namespace demoplan::ui {

namespace {

QString q(const std::string& s) { return QString::fromStdString(s); }

// A line edit with a "…" button that fills it from a file dialog.
QWidget* fileRow(QWidget* parent, QLineEdit* edit, const std::function<QString()>& choose) {
  auto* row = new QWidget(parent);
  auto* h = new QHBoxLayout(row);
  h->setContentsMargins(0, 0, 0, 0);
  h->addWidget(edit, 1);
  auto* browse = new QPushButton(QStringLiteral("…"), row);
  browse->setMaximumWidth(32);
  QObject::connect(browse, &QPushButton::clicked, row, [edit, choose] {
    const QString f = choose();
    if (!f.isEmpty()) edit->setText(f);
  });
  h->addWidget(browse);
  return row;
}

}  // namespace

CalibrationDialog::CalibrationDialog(Document* doc, QWidget* parent) : QDialog(parent), doc_(doc) {
  setWindowTitle(tr("Calibrate Camera"));
  auto* layout = new QVBoxLayout(this);
  auto* intro = new QLabel(tr("Film the printed ChArUco board (demoplan-cli board makes one) from many angles and "
                              "distances, filling the image at times, with the camera and lens of the cell."),
                           this);
  intro->setWordWrap(true);
  layout->addWidget(intro);
  auto* form = new QFormLayout;
  source_ = new QLineEdit(this);
  source_->setPlaceholderText(tr("a video, or a folder of images"));
  form->addRow(tr("Recording"), fileRow(this, source_, [this] {
                 return QFileDialog::getOpenFileName(this, tr("The board video"), {},
                                                     tr("Videos (*.mp4 *.mkv *.avi *.mov);;All files (*)"));
               }));
  board_ = new QLineEdit(this);
  board_->setPlaceholderText(tr("board.json (demoplan-charuco-board)"));
  form->addRow(tr("Board"), fileRow(this, board_, [this] {
                 return QFileDialog::getOpenFileName(this, tr("The board file"), {}, tr("Board files (*.json)"));
               }));
  layout->addLayout(form);

  auto* run_row = new QHBoxLayout;
  progress_ = new QProgressBar(this);
  progress_->setRange(0, 1);
  progress_->setValue(0);
  progress_->setFormat(tr("idle"));
  progress_->setTextVisible(true);
  start_ = new QPushButton(tr("Calibrate"), this);
  start_->setDefault(true);
  cancel_ = new QPushButton(tr("Cancel"), this);
  cancel_->setEnabled(false);
  run_row->addWidget(progress_, 1);
  run_row->addWidget(start_);
  run_row->addWidget(cancel_);
  layout->addLayout(run_row);

  summary_ = new QLabel(this);
  summary_->setWordWrap(true);
  summary_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  layout->addWidget(summary_);
  plot_ = new CalibrationErrorPlot(this);
  layout->addWidget(plot_, 1);

  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
  use_ = buttons->addButton(tr("Use This Camera…"), QDialogButtonBox::ApplyRole);
  use_->setEnabled(false);
  use_->setToolTip(tr("Write the camera file and use it for this project's video"));
  layout->addWidget(buttons);

  connect(start_, &QPushButton::clicked, this, &CalibrationDialog::start);
  connect(cancel_, &QPushButton::clicked, this, &CalibrationDialog::cancel);
  connect(use_, &QPushButton::clicked, this, &CalibrationDialog::chooseUseFile);
  connect(buttons, &QDialogButtonBox::rejected, this, [this] {
    cancel();
    reject();
  });
  connect(&runner_, &CalibrationRunner::progress, this, [this](int done, int total) {
    progress_->setRange(0, std::max(1, total));
    progress_->setValue(done);
    progress_->setFormat(tr("view %1 of %2").arg(done).arg(total));
  });
  connect(&runner_, &CalibrationRunner::finished, this, &CalibrationDialog::onFinished);
  resize(620, 480);
}

void CalibrationDialog::setSource(const QString& f) { source_->setText(f); }
void CalibrationDialog::setBoard(const QString& f) { board_->setText(f); }

bool CalibrationDialog::start() {
  if (source_->text().isEmpty() || board_->text().isEmpty()) {
    showError(tr("Choose the board recording and the board file first."));
    return false;
  }
  result_.reset();
  plot_->clear();
  use_->setEnabled(false);
  summary_->setStyleSheet({});
  summary_->setText(tr("Looking for the board in the views…"));
  progress_->setRange(0, 0);  // busy until the first view
  progress_->setFormat(tr("opening…"));
  if (!runner_.start(source_->text().toStdString(), board_->text().toStdString())) return false;
  start_->setEnabled(false);
  cancel_->setEnabled(true);
  return true;
}

void CalibrationDialog::cancel() {
  if (!runner_.isRunning()) return;
  runner_.cancel();
  start_->setEnabled(true);
  cancel_->setEnabled(false);
  progress_->setRange(0, 1);
  progress_->setValue(0);
  progress_->setFormat(tr("cancelled"));
  summary_->setText(tr("Cancelled: nothing changed."));
}

void CalibrationDialog::showError(const QString& text) {
  summary_->setStyleSheet(QStringLiteral("color: #c62828"));
  summary_->setText(text);
}

void CalibrationDialog::onFinished(const CalibrationOutcome& o) {
  start_->setEnabled(true);
  cancel_->setEnabled(false);
  progress_->setRange(0, 1);
  progress_->setValue(o.ok ? 1 : 0);
  progress_->setFormat(o.ok ? tr("done") : tr("failed"));
  if (!o.ok) {
    showError(o.error.empty() ? tr("Cancelled") : q(o.error));
    return;
  }
  result_ = o.calibration;
  const auto& r = *result_;
  const auto& c = r.camera;
  summary_->setStyleSheet({});
  summary_->setText(tr("<b>RMS %1 px</b> over %2 views (%3 left out) in %4 s<br>fx %5, fy %6, cx %7, cy %8 px; "
                       "image %9 x %10")
                        .arg(r.rms_px, 0, 'f', 3)
                        .arg(r.views_used)
                        .arg(r.views_rejected)
                        .arg(r.seconds, 0, 'f', 1)
                        .arg(c.fx, 0, 'f', 1)
                        .arg(c.fy, 0, 'f', 1)
                        .arg(c.cx, 0, 'f', 1)
                        .arg(c.cy, 0, 'f', 1)
                        .arg(c.image_size.width)
                        .arg(c.image_size.height));
  plot_->setCalibration(r.views, r.rms_px);
  use_->setEnabled(doc_->hasProject());
}

bool CalibrationDialog::useCamera(const QString& camera_file) {
  if (!result_) return false;
  perception::Camera camera = result_->camera;
  if (const perception::Camera* old = doc_->media()->camera()) {
    camera.world_T_camera = old->world_T_camera;
    camera.board = old->board;
  }
  try {
    perception::save_camera(camera_file.toStdString(), camera);
  } catch (const InputError& e) {
    showError(q(e.what()));
    return false;
  }
  doc_->setMediaFile(Media::File::Camera, QFileInfo(camera_file).absoluteFilePath());
  summary_->setText(summary_->text() + tr("<br>Written to %1 and used for this project.").arg(camera_file));
  return true;
}

void CalibrationDialog::chooseUseFile() {
  const QString dir = doc_->filePath().isEmpty() ? QString() : QFileInfo(doc_->filePath()).absolutePath();
  const QString f = QFileDialog::getSaveFileName(this, tr("Save the camera as"), dir + QStringLiteral("/camera.json"),
                                                 tr("Camera files (*.json)"));
  if (!f.isEmpty()) useCamera(f);
}

}  // namespace demoplan::ui
