#pragma once
// KUKA KR C4: a KRL module, FILE.src with the motions and FILE.dat with one E6AXIS joint target
// (degrees) per waypoint. Each block between two rests is one PTP_SPLINE of SPTP points (the
// spline passes through every point) or, with krl_ptp, PTP points approximated with C_PTP;
// never both in one block. Arm joints map to A1..A6; a 7-axis arm puts its third joint on E1
// (KUKA's convention for the LBR on KR C controllers). Mobile bases are refused. The gripper is
// driven by $OUT.
#include "core/export/program_writer.h"

namespace demoplan {

// The file is NAME.src (NAME the module name); NAME.dat is the second file, beside it.
const ProgramWriter& krl_writer();

}  // namespace demoplan
