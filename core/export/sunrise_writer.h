#pragma once
// KUKA Sunrise (Java) application for the LBR iiwa and the KMR iiwa: the waypoints as
// JointPosition constants (radians); each block between two rests is one SplineJP of ptp
// segments through them. On the KMR the platform and the arm are separate devices that Sunrise
// does not interpolate together: where the base moves, the segment is a MobilePlatformRelativeMotion
// (in the platform's frame at the start of the move) followed by the arm's ptp, so between those
// waypoints the motion is not the planned one (the header says so). The gripper is driven by an
// output of an I/O group (default: the media flange's X3 pin 1).
#include "core/export/program_writer.h"

namespace demoplan {

// The file is CLASSNAME.java; the class name is its stem.
const ProgramWriter& sunrise_writer();

}  // namespace demoplan
