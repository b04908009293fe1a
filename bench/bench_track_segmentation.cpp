// segment_tracks on tracks of growing length: three parts, a carry every 100 frames (each part
// in turn), 2 mm of noise and 3 % outliers. The cut is quadratic in the frames with rests
// subsampled to 96 samples; this says what a minute of video costs.
#include <random>

#include <benchmark/benchmark.h>

#include "perception/events/track_segmentation.h"

namespace {

demoplan::perception::PoseTracks make_tracks(int frames) {
  demoplan::perception::PoseTracks t;
  t.frames = frames;
  t.object_ids = {"a", "b", "c"};
  t.planning = {true, true, true};
  t.samples.assign(3, std::vector<demoplan::perception::PoseSample>(frames));
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0.0, 0.002);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int o = 0; o < 3; ++o) {
    Eigen::Vector3d at(0.2 * o, 0.5, 0.85), to = at;
    for (int f = 0; f < frames; ++f) {
      const int phase = f % 100, carrier = (f / 100) % 3;
      if (carrier == o && phase == 40) to = Eigen::Vector3d(u(rng), u(rng), 0.85);
      Eigen::Vector3d p = at;
      if (carrier == o && phase > 40 && phase <= 60) p = at + (to - at) * (phase - 40) / 20.0;
      if (carrier == o && phase == 60) at = to;
      auto& s = t.samples[o][f];
      s.valid = true;
      s.confidence = 1.0;
      s.pose = demoplan::Pose::Identity();
      s.pose.translation() = p + Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
      if (u(rng) < 0.03) s.pose.translation().x() += 0.3;
    }
  }
  return t;
}

void SegmentTracks(benchmark::State& state) {
  const auto tracks = make_tracks(static_cast<int>(state.range(0)));
  size_t carries = 0;
  for (auto _ : state) carries = demoplan::perception::segment_tracks(tracks).contacts(tracks).carries.size();
  state.counters["frames"] = static_cast<double>(state.range(0));
  state.counters["carries"] = static_cast<double>(carries);
}
BENCHMARK(SegmentTracks)->Arg(150)->Arg(600)->Arg(1800)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
