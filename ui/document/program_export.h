#pragma once
// The export job (core/export/export_job.h) as the export dialog runs it: never throws, says why
// there is no program, and gives the preview text. Nothing here touches the disk.
#include <string>
#include <vector>

#include "core/export/export_job.h"

namespace demoplan::ui {

struct ProgramExport : ExportReport {
  bool ok = false;    // the program is in `files`
  std::string error;  // why it is not
};

// Runs the export job; `data_dir` gives the mobile base's joints (robots.json).
ProgramExport run_program_export(const Scene& scene, const Path& path, const std::string& data_dir,
                                 ExportSettings settings);

// The files one after the other, each under a "// ---- NAME" line when there are several; a JSON
// file written on one line is shown indented (readable_json).
std::string program_preview_text(const std::vector<ProgramFile>& files);

}  // namespace demoplan::ui
