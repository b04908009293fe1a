#include "ui/document/program_export.h"

#include <filesystem>

#include "core/export/export_common.h"
#include "ui/document/json_preview.h"

namespace demoplan::ui {

ProgramExport run_program_export(const Scene& scene, const Path& path, const std::string& data_dir,
                                 ExportSettings settings) {
  ProgramExport r;
  try {
    settings.base_joints = benchmark_base_joints(data_dir, scene.robot.name);
    static_cast<ExportReport&>(r) = run_export_job(scene, path, settings);
    if (!r.check_ok)
      r.error = "the timed trajectory fails the independent check: " +
                (r.violations.empty() ? std::string("(no detail)") : r.violations.front());
    r.ok = r.check_ok;
  } catch (const std::exception& e) {
    r.error = e.what();
  }
  return r;
}

std::string program_preview_text(const std::vector<ProgramFile>& files) {
  std::string text;
  for (const ProgramFile& f : files) {
    if (files.size() > 1) text += "// ---- " + std::filesystem::path(f.name).filename().string() + "\n";
    text += f.name.ends_with(".json") ? readable_json(f.text) : f.text;
    if (!text.empty() && text.back() != '\n') text += '\n';
  }
  return text;
}

}  // namespace demoplan::ui
