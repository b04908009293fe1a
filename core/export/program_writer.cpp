#include "core/export/program_writer.h"

namespace demoplan {

double ProgramWriter::sample_rate(const ExportOptions& options) const {
  if (format_.fixed_rate) return format_.default_rate;
  return options.rate > 0 ? options.rate : format_.default_rate;
}

std::string ProgramWriter::file_stem(const std::string& stem) { return identifier(stem, "job_"); }

std::string ProgramWriter::file_name(const std::string& stem) const { return file_stem(stem) + format_.extension; }

}  // namespace demoplan
