#pragma once
// A program file as a writer produces it, in memory, and the one place that puts such files on
// disk (atomically, so a controller never picks up half a program).
#include <string>
#include <vector>

namespace demoplan {

struct ProgramFile {
  std::string name;  // where it goes: the file asked for, or a companion beside it (KRL's .dat)
  std::string text;
};

// Writes to a temporary file beside `path`, then renames it over `path`. Throws InputError.
void write_text_file_atomic(const std::string& path, const std::string& text);
// Each file atomically, in order. Throws InputError naming the file that could not be written.
void write_program_files(const std::vector<ProgramFile>& files);

}  // namespace demoplan
