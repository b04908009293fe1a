#pragma once
// CSV: '#' header comment lines, then one row per sample: time (s), every arm and base joint's
// position and velocity, the gripper state (0 open, 1 closed) and the waypoint reached at that
// sample (-1 if none). Samples every 1/rate s plus one exactly at each waypoint.
#include "core/export/program_writer.h"

namespace demoplan {

const ProgramWriter& csv_writer();

}  // namespace demoplan
