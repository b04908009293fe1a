#include "perception/video/video_reader.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <vector>
#include <filesystem>

#include "core/error.h"
#include "perception/video/ffmpeg_log.h"

namespace demoplan::perception {

namespace {
std::string frame_field(int index) { return "frame " + std::to_string(index); }

// Why an ISO media file (mp4, mov, m4a) that FFmpeg would not open cannot be read, when the reason
// is plain from its boxes: no track whose handler is 'vide' (an audio-only mp4). Empty otherwise.
std::string iso_media_problem(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string head(12, '\0');
  if (!in.read(head.data(), 12) || head.compare(4, 4, "ftyp") != 0) return {};
  in.seekg(0);
  std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (data.find("moov") == std::string::npos) return {};
  std::vector<std::string> handlers;
  for (size_t at = data.find("hdlr"); at != std::string::npos && at + 16 <= data.size(); at = data.find("hdlr", at + 4))
    handlers.push_back(data.substr(at + 12, 4));
  if (handlers.empty()) return {};
  for (const auto& h : handlers)
    if (h == "vide") return {};
  const bool audio = std::find(handlers.begin(), handlers.end(), "soun") != handlers.end();
  return std::string("the file has no video stream") + (audio ? " (only audio)" : "");
}
}  // namespace

VideoReader::VideoReader(const std::string& path, size_t cache_frames) : path_(path), cache_(cache_frames) {
  if (!std::filesystem::is_regular_file(path)) throw InputError(path, "", "video file not found");
  if (std::filesystem::file_size(path) == 0) throw InputError(path, frame_field(0), "the file is empty");
  quiet_ffmpeg_log();
  capture_.open(path, cv::CAP_FFMPEG);
  if (!capture_.isOpened()) {
    if (const std::string why = iso_media_problem(path); !why.empty()) throw InputError(path, "video stream", why);
    throw InputError(path, frame_field(0),
                     "cannot open the video: unsupported format, or the file is corrupt or truncated");
  }
  fps_ = capture_.get(cv::CAP_PROP_FPS);
  if (!(fps_ > 0.0) || !std::isfinite(fps_)) throw InputError(path, "fps", "the video has no valid frame rate");
  frame_count_ = static_cast<int>(std::lround(capture_.get(cv::CAP_PROP_FRAME_COUNT)));
  size_ = {static_cast<int>(capture_.get(cv::CAP_PROP_FRAME_WIDTH)),
           static_cast<int>(capture_.get(cv::CAP_PROP_FRAME_HEIGHT))};
  cv::Mat first;
  if (!capture_.read(first) || first.empty())
    throw InputError(path, frame_field(0), "cannot decode the first frame: the file is corrupt or truncated");
  next_ = 1;
  cache_.put(0, first);
  size_ = first.size();
  if (frame_count_ <= 0) {
    // The container announces no length: count by decoding once.
    int n = 1;
    while (capture_.grab()) ++n;
    frame_count_ = n;
    capture_.set(cv::CAP_PROP_POS_FRAMES, 1);
  }
}

cv::Mat VideoReader::frame(int index) {
  if (index < 0 || index >= frame_count_)
    throw InputError(path_, frame_field(index),
                     "out of range (the video has " + std::to_string(frame_count_) + " frames)");
  if (auto cached = cache_.get(index)) return *cached;
  cv::Mat image = decode(index);
  cache_.put(index, image);
  return image;
}

cv::Mat VideoReader::decode(int index) {
  if (index != next_) {
    capture_.set(cv::CAP_PROP_POS_FRAMES, index);
    next_ = index;
  }
  cv::Mat image;
  if (!capture_.read(image) || image.empty()) {
    next_ = -1;  // the decoder's position is unknown now: seek next time
    throw InputError(path_, frame_field(index),
                     "cannot decode: the file is truncated or corrupt (it announces " +
                         std::to_string(frame_count_) + " frames)");
  }
  if (image.size() != size_)
    throw InputError(path_, frame_field(index), "frame size changes within the video");
  ++next_;
  return image;
}

}  // namespace demoplan::perception
