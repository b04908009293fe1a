#include "perception/extraction/tracks_overlay.h"

#include <optional>
#include <stdexcept>

#include <opencv2/imgproc.hpp>

#include "perception/render/rasterizer.h"
#include "perception/video/video_reader.h"
#include "perception/video/video_writer.h"

namespace demoplan::perception {

void write_tracks_overlay(const std::string& video_path, const Camera& camera, const PoseTracks& tracks,
                          const std::vector<RenderMesh>& meshes, const std::string& out) {
  if (!camera.world_T_camera) throw std::logic_error("write_tracks_overlay: the camera has no pose");
  if (meshes.size() != tracks.object_ids.size()) throw std::logic_error("write_tracks_overlay: a mesh per track row");
  std::vector<RenderMesh> silhouettes;
  for (const auto& m : meshes) silhouettes.push_back(m.geometry());
  VideoReader video(video_path, 2);
  VideoWriter writer(out, video.fps(), video.size());
  std::vector<std::optional<Pose>> last(tracks.object_ids.size());
  Rasterizer r(video.size(), camera.fx, camera.fy, camera.cx, camera.cy, *camera.world_T_camera);
  for (int f = 0; f < video.frame_count(); ++f) {
    cv::Mat frame = video.frame(f).clone();
    for (size_t k = 0; k < silhouettes.size(); ++k) {
      const bool seen = f < tracks.frames && tracks.samples[k][f].valid;
      if (seen) last[k] = tracks.samples[k][f].pose;
      if (!last[k]) continue;
      r.clear({0, 0, 0}, {0, 0, 0});
      r.draw(silhouettes[k], *last[k]);
      std::vector<std::vector<cv::Point>> outline;
      cv::findContours(cv::Mat(r.depth() < 1e9f), outline, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_SIMPLE);
      const cv::Scalar colour = seen ? cv::Scalar(60, 220, 60) : cv::Scalar(40, 40, 230);
      cv::drawContours(frame, outline, -1, colour, 1, cv::LINE_AA);
      if (!outline.empty()) {
        const cv::Rect box = cv::boundingRect(outline.front());
        cv::putText(frame, tracks.object_ids[k], box.tl() + cv::Point(0, -4), cv::FONT_HERSHEY_SIMPLEX, 0.45, colour, 1, cv::LINE_AA);
      }
    }
    cv::putText(frame, "frame " + std::to_string(f), {12, 26}, cv::FONT_HERSHEY_SIMPLEX, 0.7, {255, 255, 255}, 2, cv::LINE_AA);
    writer.write(frame);
  }
  writer.finish();
}

}  // namespace demoplan::perception
