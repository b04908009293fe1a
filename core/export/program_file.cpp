#include "core/export/program_file.h"

#include <filesystem>
#include <fstream>

#include "core/error.h"

namespace demoplan {

void write_text_file_atomic(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw InputError(path, "", "cannot write file");
    out << text;
    out.flush();
    if (!out) throw InputError(path, "", "write failed");
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) throw InputError(path, "", "cannot replace file: " + ec.message());
}

void write_program_files(const std::vector<ProgramFile>& files) {
  for (const ProgramFile& f : files) write_text_file_atomic(f.name, f.text);
}

}  // namespace demoplan
