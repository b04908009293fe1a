#include "perception/extraction/tracks_file.h"

#include <filesystem>

#include "core/error.h"
#include "perception/io/pose_json.h"

namespace demoplan::perception {

namespace {

constexpr const char* kFormat = "demoplan-pose-tracks";
constexpr int kVersion = 1;

Json samples_to_json(const std::vector<PoseSample>& samples) {
  Json out = Json::array();
  for (int f = 0; f < static_cast<int>(samples.size()); ++f) {
    const PoseSample& s = samples[f];
    if (!s.valid) continue;
    const Eigen::Quaterniond q(s.pose.linear());
    const Eigen::Vector3d t = s.pose.translation();
    out.push_back({f, t.x(), t.y(), t.z(), q.x(), q.y(), q.z(), q.w(), s.confidence});
  }
  return out;
}

void samples_from_json(const JsonField& list, std::vector<PoseSample>& samples) {
  for (size_t i = 0; i < list.size(); ++i) {
    const JsonField row = list[i];
    if (row.size() != 9) row.fail("a sample is [frame, tx, ty, tz, qx, qy, qz, qw, confidence]");
    const int f = row[0].integer();
    if (f < 0 || f >= static_cast<int>(samples.size())) row[0].fail("frame out of range");
    const Eigen::Quaterniond q(row[7].number(), row[4].number(), row[5].number(), row[6].number());
    if (q.norm() < 1e-9) row.fail("zero quaternion");
    PoseSample& s = samples[f];
    s.valid = true;
    s.pose = pose_from_xyz_quat({row[1].number(), row[2].number(), row[3].number()}, q);
    s.confidence = row[8].number();
  }
}

}  // namespace

std::string tracks_path_for(const std::string& demonstration_path) {
  const std::filesystem::path p(demonstration_path);
  return (p.parent_path() / (p.stem().string() + ".tracks.json")).string();
}

void save_tracks_file(const std::string& path, const ExtractionResult& r) {
  Json objects = Json::array();
  for (size_t k = 0; k < r.raw.object_ids.size(); ++k) {
    Json motions = Json::array();
    auto add = [&](const std::vector<MotionInterval>& list, const char* kind) {
      for (const auto& m : list)
        if (m.object == static_cast<int>(k)) motions.push_back({{"start", m.start}, {"end", m.end}, {"kind", kind}});
    };
    add(r.contacts.carries, "carry");
    add(r.contacts.transports, "transport");
    add(r.contacts.rejected, "rejected");
    objects.push_back({{"id", r.raw.object_ids[k]},
                       {"planning", static_cast<bool>(r.raw.planning[k])},
                       {"raw", samples_to_json(r.raw.samples[k])},
                       {"smoothed", samples_to_json(r.smoothed.samples[k])},
                       {"motions", motions}});
  }
  const Json j{{"format", kFormat},
               {"version", kVersion},
               {"fps", r.raw.fps},
               {"frames", r.frames},
               {"sample_layout", "[frame, tx, ty, tz, qx, qy, qz, qw, confidence]; world pose of the part, metres"},
               {"extraction",
                {{"seconds", r.seconds},
                 {"frames_per_second", r.frames_per_second},
                 {"extrinsics", r.extrinsics_source},
                 {"tracker", r.tracker},
                 {"world_T_camera", pose_to_json(r.world_T_camera)}}},
               {"objects", objects}};
  write_json_file_atomic(path, j, -1);
}

TracksFile load_tracks_file(const std::string& path) {
  const Json json = read_json_file(path);
  const JsonField root(json, path);
  check_format(root, kFormat, kVersion);
  TracksFile t;
  const double fps = root["fps"].number();
  const int frames = root["frames"].integer();
  if (frames < 0) root["frames"].fail("must be >= 0");
  const JsonField ex = root["extraction"];
  t.seconds = ex["seconds"].number();
  t.frames_per_second = ex["frames_per_second"].number();
  t.extrinsics = ex["extrinsics"].string();
  if (ex.has("tracker")) t.tracker = ex["tracker"].string();  // files written before trackers were named lack it
  const JsonField objects = root["objects"];
  // Every object gets a sample per frame, in memory: "frames": 2147483647 asked for 400 GB
  // (found by fuzzing). Two million samples per track set is an hour of video at 30 fps with 18
  // parts.
  constexpr double kMaxSamples = 2e6;
  if (static_cast<double>(frames) * static_cast<double>(objects.size()) > kMaxSamples)
    root["frames"].fail("frames x objects = " + std::to_string(frames) + " x " + std::to_string(objects.size()) +
                        " is more than the 2000000 pose samples a tracks file may hold");
  for (PoseTracks* tracks : {&t.raw, &t.smoothed}) {
    tracks->fps = fps;
    for (size_t i = 0; i < objects.size(); ++i) {
      tracks->object_ids.push_back(objects[i]["id"].string());
      tracks->planning.push_back(objects[i]["planning"].boolean());
    }
    tracks->resize(frames);
  }
  for (size_t i = 0; i < objects.size(); ++i) {
    samples_from_json(objects[i]["raw"], t.raw.samples[i]);
    samples_from_json(objects[i]["smoothed"], t.smoothed.samples[i]);
  }
  return t;
}

}  // namespace demoplan::perception
