#pragma once
// The tracks drawn over their video, for checking a tracker by eye: each part's silhouette
// outline where its track puts it (green where the part was seen in that frame, red at its
// last pose where it was not), with the frame number and the part ids.
#include <string>
#include <vector>

#include "perception/camera/camera_model.h"
#include "perception/render/render_mesh.h"
#include "perception/tracking/pose_track.h"

namespace demoplan::perception {

// `camera` needs its world_T_camera; `meshes` are in the tracks' row order. Writes `out`
// (mp4v; .avi/.mkv as VideoWriter takes them). Throws InputError for unreadable input.
void write_tracks_overlay(const std::string& video, const Camera& camera, const PoseTracks& tracks,
                          const std::vector<RenderMesh>& meshes, const std::string& out);

}  // namespace demoplan::perception
