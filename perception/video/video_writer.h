#pragma once
// Writing a video file frame by frame; the file appears at its path only when complete
// (written beside it under a temporary name, then renamed).
#include <string>

#include <opencv2/core.hpp>
#include <opencv2/videoio.hpp>

namespace demoplan::perception {

class VideoWriter {
public:
  // fourcc: "mp4v" (default; MPEG-4 part 2), "avc1" (H.264), "MJPG", "FFV1" (lossless), ...
  // The container follows the extension of `path` (.mp4, .avi, .mkv). Throws InputError when
  // the codec or container is not available.
  VideoWriter(const std::string& path, double fps, cv::Size size, const std::string& fourcc = "mp4v");
  ~VideoWriter();  // abandons (deletes) an unfinished file
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;

  void write(const cv::Mat& bgr);
  void finish();  // closes the file and moves it into place

  int frames_written() const { return frames_; }

private:
  std::string path_, tmp_;
  cv::Size size_;
  cv::VideoWriter writer_;
  int frames_ = 0;
  bool finished_ = false;
};

}  // namespace demoplan::perception
