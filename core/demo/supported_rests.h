#pragma once
// Every resting pose the planner plans to must pass the validator's placement test (gtamp
// README 6): a part released where no support holds it (put inside a shelf where the camera
// never saw it land, its pose where it was last seen, in the air) makes every path fail
// validation after minutes of planning. Such rests are found before planning and named: the
// event, its frame, the part, and how far it is from the nearest support.
#include <string>
#include <vector>

#include "core/demo/demonstration.h"
#include "core/scene/scene.h"

namespace demoplan {

struct UnsupportedRest {
  int event = -1;  // the event whose pose is the rest: the part's first grasp, or a release
  int frame = 0;
  int object = -1;
  // "YCBV_03 rests on no support: 41 mm above the nearest (shelf/board_2); move it onto a support"
  std::string message;
};

// The rests of `demo` that the placement test refuses, with the robot at its initial
// configuration: each part where it is first grasped (where the first event sees a part never
// grasped) and where each release puts it, as the constraint graph takes them. Poses on a robot
// link (pose_frames) are the deck placement's and are not checked; nor is a demonstration that
// breaks validate()'s rules or does not list the scene's parts (the graph names those).
std::vector<UnsupportedRest> unsupported_rests(const Scene& scene, const Demonstration& demo);

// `demo` settled on its supports (settle_on_supports: a rest within 2 cm of one is put on it),
// ready for the planner. Throws InputError(source, "events[i] (frame f)", message) for the first
// rest still unsupported.
Demonstration settle_for_planning(const Scene& scene, Demonstration demo, const std::string& source);

}  // namespace demoplan
