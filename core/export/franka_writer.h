#pragma once
// Franka (Panda): a JSON joint trajectory at 1 kHz for a libfranka joint-position motion
// generator. The motion is cut at the rests into steps; between two motion steps a gripper step
// (franka::Gripper grasp or move) runs while the arm stands still. Each motion step starts and
// ends at rest, so the generator's first command equals the robot's state and it can return
// motion_finished on the last. Positions are continuous to the third derivative within
// Franka's published limits (checked by finite differences at 1 kHz in the tests).
#include "core/export/program_writer.h"

namespace demoplan {

const ProgramWriter& franka_writer();

}  // namespace demoplan
