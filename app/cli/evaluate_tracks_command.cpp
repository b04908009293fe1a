// demoplan-cli evaluate-tracks: the events and rest poses detected from a benchmark task's pose
// tracks alone against its contact labels and cleaned key poses. The only place the labels are
// read on the tracks' path.
#include <algorithm>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "app/cli/command.h"
#include "core/demo/benchmark_demonstration.h"
#include "core/demo/benchmark_scene.h"
#include "core/statistics.h"
#include "perception/events/evaluation.h"
#include "perception/events/tracks_demonstration.h"

namespace demoplan::cli {

namespace {

struct EvaluateTracksOptions {
  std::string task = "shelf_1", robot, data_dir;
  bool json = false;
  perception::TrackSegmentationOptions segmentation;
};

double max_of(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end()); }

std::vector<std::string> pick_sequence(const Demonstration& d) {
  std::vector<std::string> out;
  for (const auto& e : d.events)
    if (e.type == EventType::Grasp) out.push_back(d.object_ids[e.object]);
  return out;
}

int run_evaluate_tracks(const EvaluateTracksOptions& o) {
  const BenchmarkTask task = load_benchmark_task(o.data_dir, o.task);
  // The scene only gives the supports the rest poses are snapped onto: any robot of the task.
  std::string robot = o.robot;
  if (robot.empty()) robot = task.robot_pose_files.count("panda") ? "panda" : task.robot_pose_files.begin()->first;
  const Scene scene = build_benchmark_scene(task, robot, 0);
  const perception::TracksDemonstration found = perception::demonstration_from_tracks(task, scene, o.segmentation);
  const Demonstration truth = demonstration_from_benchmark(task, scene, PoseSource::Subgoals);
  const auto e2 = perception::evaluate_demonstration(found.demonstration, truth, 2);
  const auto e5 = perception::evaluate_demonstration(found.demonstration, truth, 5);
  std::vector<double> offsets;
  for (const auto& m : e5.matches) offsets.push_back(m.timing_error);
  const auto seq_found = pick_sequence(found.demonstration), seq_true = pick_sequence(truth);
  const bool sequence_correct = seq_found == seq_true;

  auto join = [](const std::vector<std::string>& v) {
    std::string s;
    for (const auto& x : v) s += (s.empty() ? "" : " ") + x;
    return s;
  };
  std::cerr << "events from the pose tracks of " << task.name() << " against its contact labels\n"
            << "  events         " << e5.truth_events << " labelled, " << e5.detected_events << " detected\n"
            << "  within 2       " << e2.matched << " matched: precision " << e2.precision << ", recall " << e2.recall << "\n"
            << "  within 5       " << e5.matched << " matched: precision " << e5.precision << ", recall " << e5.recall << "\n"
            << "  signed offset  " << median(offsets) << " frames (median, detected - labelled)\n"
            << "  picks          " << join(seq_found) << (sequence_correct ? " (as labelled)" : " (labelled: " + join(seq_true) + ")")
            << "\n"
            << "  rest poses     " << median(e5.translation_errors_mm) << " mm median, " << max_of(e5.translation_errors_mm)
            << " mm max; " << median(e5.rotation_errors_deg) << " deg median, " << max_of(e5.rotation_errors_deg)
            << " deg max (" << e5.pose_pairs << " world poses at matched events)\n";
  for (size_t i = 0; i < found.tracks.object_ids.size(); ++i) {
    const auto& seg = found.segmentation.objects[i];
    std::cerr << "  " << found.tracks.object_ids[i] << ": noise " << seg.noise.sigma_min * 1000 << "-"
              << seg.noise.sigma_max * 1000 << " mm;";
    for (const auto& s : seg.segments)
      std::cerr << " " << perception::segment_kind_name(s.kind) << " " << s.first << "-" << s.last;
    std::cerr << "\n";
  }
  for (const auto& m : e5.matches) {
    const auto& e = truth.events[m.truth];
    std::cerr << "  " << (e.type == EventType::Grasp ? "grasp   " : "release ") << truth.object_ids[e.object] << " labelled "
              << e.frame << ", detected " << e.frame + m.timing_error << "\n";
  }
  // Where the rest poses are farthest from the cleaned ones, for the operator to look at.
  double worst = 0;
  std::string worst_at;
  Eigen::Vector3d worst_offset = Eigen::Vector3d::Zero();
  for (const auto& m : e5.matches) {
    const auto& et = truth.events[m.truth];
    const auto& ed = found.demonstration.events[m.detected];
    for (size_t k = 0; k < truth.object_ids.size(); ++k) {
      if (!et.pose_frame(static_cast<int>(k)).empty() || !ed.pose_frame(static_cast<int>(k)).empty()) continue;
      const double mm = (et.poses[k].translation() - ed.poses[k].translation()).norm() * 1000;
      if (mm > worst) {
        worst = mm, worst_at = truth.object_ids[k] + " at the labelled event of frame " + std::to_string(et.frame);
        worst_offset = (ed.poses[k].translation() - et.poses[k].translation()) * 1000;
      }
    }
  }
  if (!worst_at.empty())
    std::cerr << "  farthest rest  " << worst << " mm: " << worst_at << " (found - cleaned: x " << worst_offset.x()
              << ", y " << worst_offset.y() << ", z " << worst_offset.z() << " mm)\n";
  for (const auto& d : found.demonstration.doubts)
    std::cerr << "  doubt: frames " << d.first_frame << "-" << d.last_frame << ": " << d.message << "\n";
  if (o.json) {
    nlohmann::json j{{"task", task.name()},
                     {"events_true", e5.truth_events},
                     {"events_detected", e5.detected_events},
                     {"matched_2", e2.matched},
                     {"matched_5", e5.matched},
                     {"precision_2", e2.precision},
                     {"recall_2", e2.recall},
                     {"precision_5", e5.precision},
                     {"recall_5", e5.recall},
                     {"median_signed_offset_frames", median(offsets)},
                     {"signed_offsets_frames", offsets},
                     {"sequence_correct", sequence_correct},
                     {"sequence_detected", seq_found},
                     {"sequence_true", seq_true},
                     {"rest_pairs", e5.pose_pairs},
                     {"rest_median_mm", median(e5.translation_errors_mm)},
                     {"rest_max_mm", max_of(e5.translation_errors_mm)},
                     {"rest_median_deg", median(e5.rotation_errors_deg)},
                     {"rest_max_deg", max_of(e5.rotation_errors_deg)},
                     {"doubts", found.demonstration.doubts.size()}};
    for (const Demonstration* d : {&found.demonstration, &truth}) {
      nlohmann::json events = nlohmann::json::array();
      for (const auto& e : d->events)
        events.push_back({{"object", d->object_ids[e.object]}, {"type", e.type == EventType::Grasp ? "grasp" : "release"},
                          {"frame", e.frame}});
      j[d == &truth ? "labelled" : "detected"] = events;
    }
    std::cout << j.dump() << std::endl;
  }
  return kOk;
}

}  // namespace

Command register_evaluate_tracks_command(CLI::App& app) {
  auto o = std::make_shared<EvaluateTracksOptions>();
  CLI::App* sub = app.add_subcommand(
      "evaluate-tracks", "events and rest poses from a benchmark task's pose tracks against its contact labels");
  sub->add_option("--task", o->task, "task as <task>_<demo>, e.g. shelf_1")->capture_default_str();
  sub->add_option("--robot", o->robot, "robot whose scene gives the supports (default: panda, else the task's robot)");
  sub->add_flag("--json", o->json, "print one JSON object on stdout");
  auto& seg = o->segmentation;
  sub->add_option("--max-rest-spread", seg.max_rest_spread, "m: a rest whose samples spread wider costs as much as moving")
      ->capture_default_str();
  sub->add_option("--outlier-sigmas", seg.outlier_sigmas, "a rest sample costs at most this many of its rest's sigmas")
      ->capture_default_str();
  sub->add_option("--motion-penalty", seg.motion_penalty, "cost of one motion")->capture_default_str();
  sub->add_option("--min-carry-distance", seg.min_carry_distance, "m: rests closer together are one rest")
      ->capture_default_str();
  add_data_dir_option(*sub, o->data_dir);
  return {sub, [o] { return run_evaluate_tracks(*o); }};
}

}  // namespace demoplan::cli
