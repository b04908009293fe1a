// demoplan-cli evaluate: compare an extracted demonstration with the ground truth.
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include <nlohmann/json.hpp>

#include "app/cli/command.h"
#include "core/demo/demonstration.h"
#include "perception/events/evaluation.h"
#include "perception/events/model_points.h"
#include "perception/extraction/tracks_file.h"
#include "perception/tracking/track_error.h"

namespace demoplan::cli {

namespace {

struct EvaluateOptions {
  std::string demo, truth, data_dir;
  int tolerance = 2;
  bool json = false;
};

int run_evaluate(const EvaluateOptions& o) {
  const Demonstration detected = load_demonstration(o.demo);
  const Demonstration truth = load_demonstration(o.truth);
  const auto models = perception::benchmark_model_points(o.data_dir, truth.task);
  const perception::DemonstrationEvaluation e = perception::evaluate_demonstration(detected, truth, o.tolerance, models);
  std::optional<double> fps;
  std::optional<perception::TrackError> per_frame;
  if (const std::string tracks = perception::tracks_path_for(o.demo); std::filesystem::exists(tracks)) {
    const perception::TracksFile estimated = perception::load_tracks_file(tracks);
    fps = estimated.frames_per_second;
    // Every frame too, when the truth has its tracks beside it (synth's truth.tracks.json).
    if (const std::string truth_tracks = perception::tracks_path_for(o.truth); std::filesystem::exists(truth_tracks))
      per_frame = perception::track_error(estimated.raw, perception::load_tracks_file(truth_tracks).raw);
  }

  std::cerr << "evaluation of " << o.demo << " against " << o.truth << " (tolerance " << o.tolerance << " frames)\n"
            << "  events              " << e.matched << " matched of " << e.truth_events << " true, "
            << e.detected_events << " detected\n"
            << "  precision / recall  " << e.precision << " / " << e.recall << "\n"
            << "  timing error        " << e.median_timing_error_frames << " frames (median)\n"
            << "  translation error   " << e.median_translation_error_mm << " mm median, " << e.max_translation_error_mm
            << " max (" << e.pose_pairs << " part poses)\n"
            << "  rotation error      " << e.median_rotation_error_deg << " deg median, " << e.max_rotation_error_deg << " max\n";
  if (e.median_mssd_mm >= 0) std::cerr << "  MSSD                " << e.median_mssd_mm << " mm median (no symmetries)\n";
  if (fps) std::cerr << "  extraction speed    " << *fps << " frames/s\n";
  if (per_frame)
    std::cerr << "  every frame         " << per_frame->median_translation_mm << " mm median, "
              << per_frame->p95_translation_mm << " mm 95th percentile, over " << per_frame->estimated_samples << " of "
              << per_frame->truth_samples << " true part poses estimated\n";
  for (const auto& m : e.matches)
    if (m.timing_error != 0)
      std::cerr << "  event " << m.truth << " off by " << m.timing_error << " frame(s)\n";
  if (o.json) {
    nlohmann::json j{{"event_precision", e.precision},
                     {"event_recall", e.recall},
                     {"median_timing_error_frames", e.median_timing_error_frames},
                     {"median_translation_error_mm", e.median_translation_error_mm},
                     {"median_rotation_error_deg", e.median_rotation_error_deg},
                     {"max_translation_error_mm", e.max_translation_error_mm},
                     {"max_rotation_error_deg", e.max_rotation_error_deg},
                     {"median_mssd_mm", e.median_mssd_mm >= 0 ? nlohmann::json(e.median_mssd_mm) : nlohmann::json()},
                     {"extraction_fps", fps ? nlohmann::json(*fps) : nlohmann::json()},
                     {"frame_median_translation_error_mm",
                      per_frame && per_frame->median_translation_mm >= 0 ? nlohmann::json(per_frame->median_translation_mm) : nlohmann::json()},
                     {"frame_p95_translation_error_mm",
                      per_frame && per_frame->p95_translation_mm >= 0 ? nlohmann::json(per_frame->p95_translation_mm) : nlohmann::json()},
                     {"frame_coverage", per_frame ? nlohmann::json(per_frame->coverage) : nlohmann::json()},
                     {"truth_events", e.truth_events},
                     {"detected_events", e.detected_events},
                     {"matched_events", e.matched},
                     {"pose_pairs", e.pose_pairs},
                     {"tolerance_frames", o.tolerance}};
    std::cout << j.dump() << std::endl;
  }
  return kOk;
}

}  // namespace

Command register_evaluate_command(CLI::App& app) {
  auto o = std::make_shared<EvaluateOptions>();
  CLI::App* sub = app.add_subcommand("evaluate", "compare an extracted demonstration with the ground truth");
  sub->add_option("demonstration", o->demo, "extracted demonstration (demoplan-demonstration JSON)")->required();
  sub->add_option("--truth", o->truth, "ground-truth demonstration")->required();
  sub->add_option("--tolerance", o->tolerance, "frames an event may be off and still match")
      ->check(CLI::NonNegativeNumber)->capture_default_str();
  sub->add_flag("--json", o->json, "print one JSON object on stdout");
  add_data_dir_option(*sub, o->data_dir);
  return {sub, [o] { return run_evaluate(*o); }};
}

}  // namespace demoplan::cli
