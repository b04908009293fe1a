#include "core/export/program_writers.h"

#include <sstream>

#include "core/error.h"
#include "core/export/csv_writer.h"
#include "core/export/franka_writer.h"
#include "core/export/krl_writer.h"
#include "core/export/ros_yaml_writer.h"
#include "core/export/sunrise_writer.h"
#include "core/export/urscript_writer.h"

namespace demoplan {

const std::vector<const ProgramWriter*>& program_writers() {
  // One line per format.
  static const std::vector<const ProgramWriter*> writers{
      &urscript_writer(),
      &krl_writer(),
      &sunrise_writer(),
      &franka_writer(),
      &ros_yaml_writer(),
      &csv_writer(),
  };
  return writers;
}

std::vector<std::string> program_format_ids() {
  std::vector<std::string> ids;
  for (const ProgramWriter* w : program_writers()) ids.push_back(w->id());
  return ids;
}

const ProgramWriter* find_program_writer(const std::string& id) {
  for (const ProgramWriter* w : program_writers())
    if (w->id() == id) return w;
  return nullptr;
}

const ProgramWriter& program_writer(const std::string& id, const std::string& file) {
  if (const ProgramWriter* w = find_program_writer(id)) return *w;
  std::string known;
  for (const std::string& k : program_format_ids()) known += (known.empty() ? "" : ", ") + k;
  throw InputError(file, "format", "unknown format '" + id + "' (" + known + ")");
}

std::string default_rates_text() {
  std::string s;
  for (const ProgramWriter* w : program_writers()) {
    std::ostringstream rate;
    rate << w->format().default_rate;
    s += (s.empty() ? "" : ", ") + w->id() + " " + rate.str() + (w->format().fixed_rate ? " only" : "");
  }
  return s;
}

}  // namespace demoplan
