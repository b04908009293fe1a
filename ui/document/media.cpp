#include "ui/document/media.h"

#include <QFileInfo>

#include "perception/camera/camera_model.h"
#include "perception/video/video_reader.h"

namespace demoplan::ui {

namespace {
std::string absolute(const QString& file) {
  return file.isEmpty() ? std::string() : QFileInfo(file).absoluteFilePath().toStdString();
}
}  // namespace

Media::Media(QObject* parent) : QObject(parent) {}
Media::~Media() = default;

void Media::openVideo(const std::string& file) {
  video_file_ = file;
  video_.reset();
  video_error_.clear();
  if (file.empty()) return;
  try {
    video_ = std::make_unique<perception::VideoReader>(file);
  } catch (const std::exception& e) {
    video_error_ = QString::fromUtf8(e.what());
  }
}

void Media::openCamera(const std::string& file) {
  camera_file_ = file;
  camera_.reset();
  camera_error_.clear();
  if (file.empty()) return;
  try {
    camera_ = std::make_unique<perception::Camera>(perception::load_camera(file));
  } catch (const std::exception& e) {
    camera_error_ = QString::fromUtf8(e.what());
  }
}

void Media::load(const std::string& video, const std::string& camera, const std::string& markers) {
  openVideo(video);
  openCamera(camera);
  markers_file_ = markers;
  emit videoChanged();
  emit cameraChanged();
  emit markersChanged();
}

void Media::use(File which, const std::string& file) {
  switch (which) {
    case File::Video:
      openVideo(file);
      emit videoChanged();
      break;
    case File::Camera:
      openCamera(file);
      emit cameraChanged();
      break;
    case File::Markers:
      markers_file_ = file;
      emit markersChanged();
      break;
  }
}

const std::string& Media::fileOf(File which) const {
  return which == File::Video ? video_file_ : which == File::Camera ? camera_file_ : markers_file_;
}

void Media::setVideo(const QString& file) {
  openVideo(absolute(file));
  emit edited();
  emit videoChanged();
}

void Media::setCamera(const QString& file) {
  openCamera(absolute(file));
  emit edited();
  emit cameraChanged();
}

void Media::setMarkers(const QString& file) {
  markers_file_ = absolute(file);
  emit edited();
  emit markersChanged();
}

}  // namespace demoplan::ui
