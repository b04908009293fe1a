#pragma once
// The recording a project refers to: the video (decoded on demand), the camera calibration and
// the marker scene (which markers are on which part). A missing or unreadable file is kept with
// its error, shown on the Video step, never fatal: the operator can locate it again.
#include <QObject>
#include <QString>
#include <memory>
#include <string>

namespace demoplan::perception {
class VideoReader;
struct Camera;
}  // namespace demoplan::perception

namespace demoplan::ui {

class Media : public QObject {
  Q_OBJECT
public:
  explicit Media(QObject* parent = nullptr);
  ~Media() override;

  // A project's files (absolute paths; empty: none), as opened: emits the *Changed signals but
  // not edited().
  void load(const std::string& video, const std::string& camera, const std::string& markers);
  // The operator's choice: also emits edited(). (In the GUI they go through the undo stack:
  // Document::setMediaFile.)
  void setVideo(const QString& file);
  void setCamera(const QString& file);
  void setMarkers(const QString& file);
  enum class File { Video, Camera, Markers };
  // Opens `file` (absolute; empty: none) as the video, camera or marker scene and emits its
  // *Changed signal, not edited(): what the undo commands call.
  void use(File which, const std::string& file);
  const std::string& fileOf(File which) const;

  const std::string& videoFile() const { return video_file_; }
  const std::string& cameraFile() const { return camera_file_; }
  const std::string& markersFile() const { return markers_file_; }
  QString videoPath() const { return QString::fromStdString(video_file_); }
  QString cameraPath() const { return QString::fromStdString(camera_file_); }
  QString markersPath() const { return QString::fromStdString(markers_file_); }
  perception::VideoReader* video() const { return video_.get(); }
  const perception::Camera* camera() const { return camera_.get(); }
  QString videoError() const { return video_error_; }
  QString cameraError() const { return camera_error_; }

signals:
  void videoChanged();
  void cameraChanged();
  void markersChanged();
  void edited();

private:
  void openVideo(const std::string& file);
  void openCamera(const std::string& file);

  std::string video_file_, camera_file_, markers_file_;
  std::unique_ptr<perception::VideoReader> video_;
  std::unique_ptr<perception::Camera> camera_;
  QString video_error_, camera_error_;
};

}  // namespace demoplan::ui
