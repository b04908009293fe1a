#pragma once
// FFmpeg writes its own messages ("moov atom not found") to stderr. demoplan reports decoding
// problems itself, in one line naming the file and frame, so FFmpeg is made quiet unless the
// user asked for its messages (OPENCV_FFMPEG_LOGLEVEL or OPENCV_FFMPEG_DEBUG set).
namespace demoplan::perception {

// Call before the first video is opened (OpenCV reads the setting once).
void quiet_ffmpeg_log();

}  // namespace demoplan::perception
