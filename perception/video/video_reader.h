#pragma once
// Reading a video file (mp4, avi, mkv: whatever OpenCV's FFmpeg backend decodes) by frame index:
// frame count, frame rate, timestamps, exact seeking and a small cache of decoded frames.
#include <string>

#include <opencv2/core.hpp>
#include <opencv2/videoio.hpp>

#include "perception/video/frame_cache.h"

namespace demoplan::perception {

class VideoReader {
public:
  // Opens the file and decodes its first frame. Throws demoplan::InputError naming the file
  // (and "frame 0") when it is missing, not a video, unsupported or cannot be decoded.
  explicit VideoReader(const std::string& path, size_t cache_frames = 32);

  const std::string& path() const { return path_; }
  int frame_count() const { return frame_count_; }
  double fps() const { return fps_; }
  cv::Size size() const { return size_; }
  // Seconds from the start of the video to frame `index` (constant frame rate).
  double timestamp(int index) const { return index / fps_; }

  // The decoded frame (BGR, 8 bit); sequential access decodes on, anything else seeks.
  // Throws InputError(path, "frame N", ...) when N is out of range or fails to decode
  // (a truncated or corrupt file). The returned image is shared with the cache: clone it to
  // modify it.
  cv::Mat frame(int index);

private:
  cv::Mat decode(int index);

  std::string path_;
  cv::VideoCapture capture_;
  int frame_count_ = 0;
  double fps_ = 0.0;
  cv::Size size_;
  int next_ = 0;  // index of the frame the capture decodes next
  FrameCache cache_;
};

}  // namespace demoplan::perception
