#pragma once
// One controller format: what the CLI and the export dialog show of it (id, label, extension,
// sample rate, file-name rule) and its writer, which produces the program in memory. Writing to
// disk is write_program_files()'s job, so a preview never touches the disk.
#include <string>
#include <utility>
#include <vector>

#include "core/export/export_common.h"
#include "core/export/program_file.h"

namespace demoplan {

// What a writer made: its files (the one asked for first), remarks for the user, and how many
// samples it streamed (sampled formats only).
struct ProgramOutput {
  std::vector<ProgramFile> files;
  std::vector<std::string> warnings;
  size_t samples = 0;
};

struct ProgramFormat {
  std::string id;         // the CLI's --format value: "urscript"
  std::string label;      // for people: "Universal Robots (URScript)"
  std::string extension;  // of the first file: ".script"
  // Hz of the streamed samples when the options give no rate; the independent trajectory check
  // samples at the same rate, so that it sees what the controller gets.
  double default_rate = 100.0;
  bool fixed_rate = false;  // the controller runs at default_rate only (libfranka: 1 kHz)
};

class ProgramWriter {
public:
  explicit ProgramWriter(ProgramFormat format) : format_(std::move(format)) {}
  virtual ~ProgramWriter() = default;
  ProgramWriter(const ProgramWriter&) = delete;
  ProgramWriter& operator=(const ProgramWriter&) = delete;

  const ProgramFormat& format() const { return format_; }
  const std::string& id() const { return format_.id; }

  // The rate the output streams at and the check samples at: the fixed rate, else the options'
  // rate, else the default.
  double sample_rate(const ExportOptions& options) const;
  // A file name this format accepts, from any stem (a project's name): by default the stem as an
  // identifier ("2 job" -> "job_2_job") plus the extension.
  virtual std::string file_name(const std::string& stem) const;
  // The program for `file` (its name gives the module or class name; errors name it). Throws
  // InputError naming `file` when the robot or the options do not fit the format.
  virtual ProgramOutput write(const ProgramInput& input, const std::string& file) const = 0;

protected:
  // The stem as the default rule makes it, before the extension.
  static std::string file_stem(const std::string& stem);

private:
  ProgramFormat format_;
};

}  // namespace demoplan
