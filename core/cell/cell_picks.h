#pragma once
// A cell's demonstration without a video: the picks a demonstrator would make (which part, put
// down where), as the events and poses extraction would find. Either given (a script), or drawn
// at random among the picks the robot can do: the part put down flat on a support, anywhere on
// it, turned any way about the vertical, clear of everything, with a handle that both grasps
// it where it is and releases it there (the pick-feasibility test). Seeded: the same seed gives
// the same picks. What synthetic cell videos are made of, and what tests plan from.
#include <cstdint>
#include <string>
#include <vector>

#include "core/demo/demonstration.h"
#include "core/scene/scene.h"

namespace demoplan {

struct ScriptedPick {
  int part = -1;  // scene object
  Pose to = Pose::Identity();  // world pose where it is put down
};

// Script file {"format": "demoplan-pick-script", "version": 1,
//              "picks": [{"part": "bracket", "to": {"xyz": [...], "rpy": [...]}}]}.
// Throws InputError naming the file and field (an unknown part, a malformed pose).
std::vector<ScriptedPick> load_pick_script(const std::string& file, const Scene& scene);

struct PickTiming {
  double fps = 30.0;
  int lead_in = 30;     // frames before the first grasp
  int carry = 45;       // frames from a grasp to its release
  int between = 30;     // frames from a release to the next grasp
};

// The events of `picks` from `start`: per pick a grasp of the part where it rests and a release
// at `to`, every part's pose at each event. `name` becomes the demonstration's task.
Demonstration demonstration_from_picks(const Scene& scene, const SceneState& start, const std::vector<ScriptedPick>& picks,
                                       const std::string& name, const PickTiming& timing = {});

struct RandomPickReport {
  std::vector<ScriptedPick> picks;
  int attempts = 0;      // target poses drawn
  std::string failure;   // when fewer picks than asked were found: why
};

// `count` picks the robot can do, each moving a part other than the previous pick's. Stops early
// (saying why) when 200 draws find no doable pick.
RandomPickReport random_picks(const Scene& scene, const SceneState& start, int count, std::uint64_t seed);

}  // namespace demoplan
