#pragma once
// The per-frame part poses of an extraction, for the UI's timeline and 3D view, written beside
// the demonstration ("<demo>.tracks.json").
//
// File "demoplan-pose-tracks" version 1 (JSON):
//   {"format": "demoplan-pose-tracks", "version": 1, "fps": 30, "frames": 150,
//    "sample_layout": "[frame, tx, ty, tz, qx, qy, qz, qw, confidence]",
//    "extraction": {"seconds": 3.2, "frames_per_second": 46.9, "extrinsics": "file", "tracker": "markers",
//                   "world_T_camera": {"t": [...], "q": [...]}},
//    "objects": [{"id": "YCBV_02", "planning": true,
//                 "raw": [[12, 0.1, 0.4, 0.86, 0, 0, 0, 1, 0.97], ...],   // frames with an estimate
//                 "smoothed": [...],                                      // what the UI draws
//                 "motions": [{"start": 9, "end": 48, "kind": "carry"}]}]}  // carry|transport|rejected
// World poses of the part frames, metres; quaternions scalar last.
#include <string>

#include "perception/extraction/extract_demonstration.h"

namespace demoplan::perception {

void save_tracks_file(const std::string& path, const ExtractionResult& result);

struct TracksFile {
  PoseTracks raw, smoothed;
  double seconds = 0.0, frames_per_second = 0.0;
  std::string extrinsics;
  std::string tracker;  // the pose tracker's name; empty in older files
};
// Throws InputError.
TracksFile load_tracks_file(const std::string& path);

// "<dir>/<stem>.tracks.json" beside a demonstration file "<dir>/<stem>.json".
std::string tracks_path_for(const std::string& demonstration_path);

}  // namespace demoplan::perception
