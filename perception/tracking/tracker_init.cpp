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
  return init;
}

void save_tracker_init(const std::string& path, const TrackerInit& init) {
  Json parts = Json::array();
  for (const auto& p : init.parts) parts.push_back({{"id", p.id}, {"world_T_object", pose_to_json(p.world_T_object)}});
  write_json_file_atomic(path, {{"format", kFormat}, {"version", kVersion}, {"frame", init.frame}, {"parts", parts}});
}

}  // namespace demoplan::perception
