#pragma once
// UR: a URScript program (.script) for a 6-axis UR arm. Default: one movej per waypoint, blend
// radius 0 at the rests and a small radius elsewhere (UR blends cut the corner within r of the
// waypoint, in TCP metres); option: the timed trajectory as a servoj stream at 125 or 500 Hz,
// which follows it exactly. The gripper is driven by standard digital outputs.
#include "core/export/program_writer.h"

namespace demoplan {

const ProgramWriter& urscript_writer();

}  // namespace demoplan
