#include "perception/video/video_writer.h"

#include <filesystem>

#include "core/error.h"
#include "perception/video/ffmpeg_log.h"

namespace demoplan::perception {

namespace fs = std::filesystem;

VideoWriter::VideoWriter(const std::string& path, double fps, cv::Size size, const std::string& fourcc)
    : path_(path), size_(size) {
  const fs::path p(path);
  tmp_ = (p.parent_path() / ("." + p.stem().string() + ".partial" + p.extension().string())).string();
  if (fourcc.size() != 4) throw InputError(path, "fourcc", "'" + fourcc + "' is not a four-character code");
  const int code = cv::VideoWriter::fourcc(fourcc[0], fourcc[1], fourcc[2], fourcc[3]);
  quiet_ffmpeg_log();
  writer_.open(tmp_, cv::CAP_FFMPEG, code, fps, size, true);
  if (!writer_.isOpened())
    throw InputError(path, "", "cannot write a '" + fourcc + "' video here (codec, container or folder)");
}

VideoWriter::~VideoWriter() {
  if (finished_) return;
  writer_.release();
  std::error_code ec;
  fs::remove(tmp_, ec);
}

void VideoWriter::write(const cv::Mat& bgr) {
  if (bgr.size() != size_ || bgr.type() != CV_8UC3)
    throw std::invalid_argument("VideoWriter::write: frame must be 8-bit BGR of the video's size");
  writer_.write(bgr);
  ++frames_;
}

void VideoWriter::finish() {
  if (finished_) return;
  writer_.release();
  std::error_code ec;
  fs::rename(tmp_, path_, ec);
  if (ec) throw InputError(path_, "", "cannot move the finished video into place: " + ec.message());
  finished_ = true;
}

}  // namespace demoplan::perception
