#include "core/placement/placement_result.h"

#include <algorithm>
#include <map>

#include "core/error.h"
#include "core/io/json_file.h"
#include "core/io/shards.h"

namespace demoplan {

namespace {

constexpr const char* kFormat = "demoplan-placement";
constexpr int kVersion = 1;
constexpr const char* kCountKey = "candidate_count";

nlohmann::json optional_number(const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(); }

nlohmann::json candidate_json(const PlacementCandidate& c) {
  nlohmann::json runs = nlohmann::json::array();
  for (const PlacementRun& r : c.runs)
    runs.push_back({{"seed", r.seed}, {"valid", r.valid}, {"planning_time_s", r.planning_time_s},
                    {"cycle_time_s", r.valid ? nlohmann::json(r.cycle_time_s) : nlohmann::json()},
                    {"path_length", r.valid ? nlohmann::json(r.path_length) : nlohmann::json()},
                    {"grasps", r.grasps}, {"message", r.message}});
  return {{"index", c.index},
          {"base_pose", {{"x", c.base.x}, {"y", c.base.y}, {"z", c.base.z}, {"yaw", c.base.yaw}}},
          {"screened", c.screened},
          {"feasible", c.feasible},
          {"reason", c.reason},
          {"screen_time_s", c.screen_time_s},
          {"success_rate", c.success_rate()},
          {"median_time_s", c.median_time_s()},
          {"cycle_time_s", optional_number(c.cycle_time_s())},
          {"path_length", optional_number(c.path_length())},
          {"runs", runs}};
}

PlacementCandidate read_candidate(const JsonField& j) {
  PlacementCandidate c;
  c.index = j["index"].integer();
  const JsonField b = j["base_pose"];
  c.base = {b["x"].number(), b["y"].number(), b["z"].number(), b["yaw"].number()};
  c.screened = j["screened"].boolean();
  c.feasible = j["feasible"].boolean();
  c.reason = j["reason"].string();
  c.screen_time_s = j["screen_time_s"].number();
  const JsonField runs = j["runs"];
  for (size_t i = 0; i < runs.size(); ++i) {
    const JsonField r = runs[i];
    PlacementRun run;
    run.seed = static_cast<std::uint64_t>(r["seed"].integer());
    run.valid = r["valid"].boolean();
    run.planning_time_s = r["planning_time_s"].number();
    if (run.valid) run.cycle_time_s = r["cycle_time_s"].number(), run.path_length = r["path_length"].number();
    run.grasps = r["grasps"].integer();
    run.message = r["message"].string();
    c.runs.push_back(run);
  }
  return c;
}

nlohmann::json furniture_json(const std::vector<Footprint>& furniture) {
  nlohmann::json out = nlohmann::json::array();
  for (const Footprint& f : furniture) {
    nlohmann::json outline = nlohmann::json::array();
    for (const Eigen::Vector2d& p : f.outline) outline.push_back({p.x(), p.y()});
    out.push_back({{"name", f.name}, {"outline", outline}});
  }
  return out;
}

}  // namespace

int PlacementResult::feasible_count() const {
  return static_cast<int>(std::count_if(candidates.begin(), candidates.end(), [](const auto& c) { return c.feasible; }));
}

std::string PlacementResult::message() const {
  if (!complete()) return "";
  for (const auto& c : candidates)
    if (c.usable()) return "";
  const size_t n = candidates.size();
  if (feasible_count() > 0)
    return std::to_string(feasible_count()) + " of " + std::to_string(n) +
           " candidates pass the screen, but no planning run found a valid path from any of them";
  // The most frequent reason, with the pick's own words.
  std::map<std::string, int> reasons;
  for (const auto& c : candidates)
    if (c.screened) ++reasons[c.reason];
  if (reasons.empty()) return "no candidate was evaluated";
  const auto top = std::max_element(reasons.begin(), reasons.end(),
                                    [](const auto& a, const auto& b) { return a.second < b.second; });
  return "no base pose of the " + std::to_string(n) + " in the region can do every pick; most often (" +
         std::to_string(top->second) + " of " + std::to_string(n) + "): " + top->first;
}

nlohmann::json placement_result_json(const PlacementResult& r) {
  nlohmann::json candidates = nlohmann::json::array(), published = nlohmann::json::array();
  for (const auto& c : r.candidates) candidates.push_back(candidate_json(c));
  for (const auto& c : r.published) published.push_back(candidate_json(c));
  nlohmann::json j{{"format", kFormat},
                   {"version", kVersion},
                   {"evaluated", r.candidates.size()},
                   {"feasible", r.feasible_count()},
                   {"cancelled", r.cancelled},
                   {"wall_time_s", r.wall_time_s},
                   {"candidates", candidates},
                   {"published", published},
                   {"furniture", furniture_json(r.furniture)}};
  write_shard_header(j, {r.arguments, r.candidate_count, r.shard, r.shards}, kCountKey);
  if (r.complete()) {
    // The candidates with a valid plan, best first: empty when nothing in the region works.
    nlohmann::json ranking = nlohmann::json::array();
    for (const auto& c : r.candidates)
      if (c.usable()) ranking.push_back(c.index);
    j["ranking"] = ranking;
    j["message"] = r.message();
  }
  return j;
}

void save_placement_result(const std::string& file, const PlacementResult& r) {
  write_json_file_atomic(file, placement_result_json(r));
}

PlacementResult load_placement_result(const std::string& file) {
  const Json json = read_json_file(file);
  const JsonField root(json, file);
  check_format(root, kFormat, kVersion, "placement result");
  PlacementResult r;
  const ShardHeader header = read_shard_header(root, kCountKey);
  r.arguments = header.arguments;
  r.candidate_count = header.items;
  r.shard = header.shard, r.shards = header.shards;
  r.wall_time_s = root["wall_time_s"].number();
  r.cancelled = root["cancelled"].boolean();
  if (root.has("furniture"))
    for (size_t i = 0; i < root["furniture"].size(); ++i) {
      const JsonField f = root["furniture"][i];
      Footprint fp{f["name"].string(), {}};
      for (size_t k = 0; k < f["outline"].size(); ++k) {
        const Eigen::VectorXd p = f["outline"][k].vector();
        if (p.size() != 2) f["outline"][k].fail("must be [x, y]");
        fp.outline.emplace_back(p.x(), p.y());
      }
      r.furniture.push_back(std::move(fp));
    }
  if (root.has("published"))
    for (size_t i = 0; i < root["published"].size(); ++i) r.published.push_back(read_candidate(root["published"][i]));
  const JsonField candidates = root["candidates"];
  for (size_t i = 0; i < candidates.size(); ++i) {
    item_index(candidates[i]["index"], r.candidate_count);
    r.candidates.push_back(read_candidate(candidates[i]));
  }
  return r;
}

PlacementResult merge_placement_results(const std::vector<std::string>& files) {
  PlacementResult out;
  ShardJoin join("search");
  for (const std::string& file : files) {
    PlacementResult part = load_placement_result(file);
    join.add(file, {part.arguments, part.candidate_count, part.shard, part.shards});
    if (part.cancelled) throw InputError(file, "cancelled", "this shard was cancelled before it finished");
    for (const auto& c : part.candidates) join.claim(file, c.index, "candidates");
    out.wall_time_s = std::max(out.wall_time_s, part.wall_time_s);
    if (!part.published.empty()) out.published = std::move(part.published);
    if (out.furniture.empty()) out.furniture = std::move(part.furniture);
    std::move(part.candidates.begin(), part.candidates.end(), std::back_inserter(out.candidates));
  }
  join.finish("candidates");
  out.arguments = join.header().arguments;
  out.candidate_count = join.header().items;
  rank_candidates(out.candidates);
  return out;
}

}  // namespace demoplan
