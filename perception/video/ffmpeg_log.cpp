#include "perception/video/ffmpeg_log.h"

#include <cstdlib>

namespace demoplan::perception {

void quiet_ffmpeg_log() {
  if (!std::getenv("OPENCV_FFMPEG_DEBUG")) setenv("OPENCV_FFMPEG_LOGLEVEL", "-8", 0);  // AV_LOG_QUIET
}

}  // namespace demoplan::perception
