#include "perception/tracking/tracker_init.h"

#include <set>

#include "core/io/json_file.h"
#include "perception/io/pose_json.h"

namespace demoplan::perception {

namespace {
constexpr const char* kFormat = "demoplan-tracker-init";
constexpr int kVersion = 1;
}  // namespace

const PartStart* TrackerInit::find(const std::string& id) const {
  for (const auto& p : parts)
    if (p.id == id) return &p;
  return nullptr;
}

TrackerInit load_tracker_init(const std::string& path) {
  const Json json = read_json_file(path);
  const JsonField root(json, path);
  check_format(root, kFormat, kVersion, "tracker start");
  TrackerInit init;
  init.frame = root.has("frame") ? root["frame"].integer() : 0;
  if (init.frame < 0) root["frame"].fail("must be >= 0");
  const JsonField parts = root["parts"];
  std::set<std::string> ids;
  for (size_t i = 0; i < parts.size(); ++i) {
    PartStart p;
    p.id = parts[i]["id"].string();
    if (!ids.insert(p.id).second) parts[i]["id"].fail("part '" + p.id + "' is given twice");
    p.world_T_object = pose_from_json(parts[i]["world_T_object"]);
    init.parts.push_back(p);
  }
  if (root.has("corrections"))
    init.corrections = read_part_corrections(
        root["corrections"], init.frame, [&](const std::string& id) { return init.find(id) != nullptr; },
        "has no start in \"parts\"", pose_from_json);
  return init;
}

void save_tracker_init(const std::string& path, const TrackerInit& init) {
  Json parts = Json::array();
  for (const auto& p : init.parts) parts.push_back({{"id", p.id}, {"world_T_object", pose_to_json(p.world_T_object)}});
  Json file = {{"format", kFormat}, {"version", kVersion}, {"frame", init.frame}, {"parts", parts}};
  if (!init.corrections.empty()) {
    Json corrections = Json::array();
    for (const auto& c : init.corrections)
      corrections.push_back({{"id", c.id}, {"frame", c.frame}, {"world_T_object", pose_to_json(c.world_T_object)}});
    file["corrections"] = corrections;
  }
  write_json_file_atomic(path, file);
}

}  // namespace demoplan::perception
