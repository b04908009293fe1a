#pragma once
// The registry of program writers: every format demoplan exports, by id, in the order the CLI's
// help and the export dialog list them. Adding a format: one writer file, one line in
// program_writers.cpp (docs/architecture.md).
#include <string>
#include <vector>

#include "core/export/program_writer.h"

namespace demoplan {

// urscript, krl, sunrise, franka, ros-yaml, csv
const std::vector<const ProgramWriter*>& program_writers();
std::vector<std::string> program_format_ids();
// nullptr for an id no writer has.
const ProgramWriter* find_program_writer(const std::string& id);
// Throws InputError(file, "format", ...) listing the known ids for an id no writer has.
const ProgramWriter& program_writer(const std::string& id, const std::string& file);
// Each format's default sample rate, for help texts: "urscript 125, ..., franka 1000 only, ...".
std::string default_rates_text();

}  // namespace demoplan
