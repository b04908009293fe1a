#pragma once
// Where objects ride on the robot's own deck. In waiter_0 the demonstrator carries objects on
// a tray; the KMR's deck (kmr_surface on kmr_link) plays the tray, and an object on the tray
// becomes an object on the deck, at its offset from the tray centre. That pose suits a human
// hand, not necessarily the arm mounted at the front of the deck: a handle that puts the
// object on the deck may be unable to take it off, or the one that takes it off may not reach
// its next placement. The chooser moves each deck pose (position on the deck polygon and yaw
// about its normal, keeping the resting face) until the picks that use it can be done, and
// keeps the demonstrated pose when they can already.
//
// An explicit stage between loading a demonstration and planning it (the CLI and the GUI call
// it; it takes seconds on waiter_0): demonstration in, adjusted demonstration and a report out.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/demo/demonstration.h"
#include "core/planning/stop_condition.h"
#include "core/scene/scene.h"

namespace demoplan {

struct DeckPlacementOptions {
  double grid_step = 0.04;          // m: candidate positions on the deck polygon
  int yaw_steps = 16;               // candidate yaws about the deck normal, from the demonstrated one
  double metres_per_radian = 0.05;  // deviation from the demonstration: 1 rad of yaw counts as this
  // Each end of a pick that touches the deck is sampled per handle: `screen_samples` first (a
  // candidate where no handle succeeds is dropped), then up to `samples` to rate it.
  int screen_samples = 8;
  int samples = 40;
  // A candidate is taken when every such end reaches this collision-free rate with a handle
  // whose other end (the grasp before, the release after) reaches it too.
  double accept_rate = 0.1;
  int max_rated = 30;  // candidates rated per rest before the best one so far is taken
  // When none reaches accept_rate: the best `refine` are rated again with `refine_samples`.
  int refine = 4;
  int refine_samples = 120;
  std::uint64_t seed = 1;
};

// One stay of one object on a robot surface, from the event that puts it there (or the start)
// to the one that takes it off (or the end).
struct DeckRest {
  int object = -1;
  std::string link;                       // robot link carrying the surface
  int first_event = -1, last_event = -1;  // the events that see the object there
  int pick_on = -1, pick_off = -1;        // the picks that put it there and take it off; -1: none
  Pose demonstrated = Pose::Identity();   // in the link frame
  Pose chosen = Pose::Identity();
  bool changed = false;
  bool feasible = false;  // every end of its picks sampled collision-free with a common handle
  double rate = 0.0;      // the weakest such end's collision-free rate, with its best handle
  std::string handle_on, handle_off;  // the best handles of pick_on and pick_off
  int candidates_rated = 0;
  double offset_m = 0.0, yaw_deg = 0.0;  // chosen relative to demonstrated (resting face centre)
  std::string note;                      // one line for the operator
};

struct DeckPlacementReport {
  std::vector<DeckRest> rests;
  double seconds = 0.0;
  bool stopped = false;  // cancelled or out of time: nothing was chosen
  bool changed() const;
  bool feasible() const;
  std::vector<std::string> notes() const;  // one per rest; says what moved and why
};

struct DeckPlacement {
  Demonstration demonstration;  // the input with the chosen deck poses (unchanged when stopped)
  DeckPlacementReport report;
};

// (rests done + fraction of the current one, rests)
using DeckPlacementProgress = std::function<void(double done, int total)>;

// Chooses the pose of every object resting on a robot surface in `demo` (events whose
// pose_frames name a robot link) and writes it into those events of the returned demonstration. For each rest, in the order
// the objects are put on the deck, the candidates are the demonstrated pose, then the same
// face resting on a grid of positions and yaws ordered by how far they are from it; a
// candidate must pass the benchmark's placement test on the surface, be collision-free against
// the robot in its initial configuration and the objects on the deck at the same time, and
// make the picks feasible: sampled with the constraint projector and the state validity of
// the demonstration's constraint graph, some handle releases the object onto the deck and some
// handle grasps it there, each with a handle that also grasps it at its previous placement or
// releases it at its next one. The picks of objects already chosen that happen while it rides
// are sampled again. Deterministic for a seed. Does nothing (and costs nothing) without rests.
DeckPlacement place_on_deck(const Scene& scene, const Demonstration& demo, const DeckPlacementOptions& options = {},
                            const StopCondition& stop = {}, const DeckPlacementProgress& progress = {});

}  // namespace demoplan
