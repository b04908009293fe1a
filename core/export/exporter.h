#pragma once
// The program formats demoplan writes, by name, and one entry point for all of them.
#include <string>
#include <vector>

#include "core/export/export_common.h"

namespace demoplan {

// urscript, krl, sunrise, franka, ros-yaml, csv
const std::vector<std::string>& export_formats();
// Throws InputError naming `file` when the robot does not fit the format, or for an unknown format.
ExportResult export_program(const std::string& format, const ExportJob& job, const std::string& file);

}  // namespace demoplan
