#include "core/export/exporter.h"

#include "core/error.h"
#include "core/export/csv_writer.h"
#include "core/export/franka_writer.h"
#include "core/export/krl_writer.h"
#include "core/export/ros_yaml_writer.h"
#include "core/export/sunrise_writer.h"
#include "core/export/urscript_writer.h"

namespace demoplan {

const std::vector<std::string>& export_formats() {
  static const std::vector<std::string> formats{"urscript", "krl", "sunrise", "franka", "ros-yaml", "csv"};
  return formats;
}

ExportResult export_program(const std::string& format, const ExportJob& job, const std::string& file) {
  if (format == "urscript") return write_urscript(job, file);
  if (format == "krl") return write_krl(job, file);
  if (format == "sunrise") return write_sunrise(job, file);
  if (format == "franka") return write_franka(job, file);
  if (format == "ros-yaml") return write_ros_yaml(job, file);
  if (format == "csv") return write_csv(job, file);
  throw InputError(file, "format", "unknown format '" + format + "' (urscript, krl, sunrise, franka, ros-yaml, csv)");
}

}  // namespace demoplan
