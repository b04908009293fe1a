#pragma once
// Shared by the libFuzzer targets (tests/fuzz/fuzz_*.cpp): the fuzzer's bytes as a file the
// project's loader opens, and the contract every loader keeps on bad input.
//
// A loader may return or throw demoplan::InputError, whose what() is one line starting with
// the file it read (DESIGN.md, "Bad input"). Anything else (another exception, a crash, an
// ASan or UBSan report, a broken message) is a finding: the target aborts and libFuzzer keeps
// the input.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.h"

namespace demoplan::fuzz {

// A folder of this process's own in the temp dir (libFuzzer's -fork children run at once),
// removed at exit. The path is never destroyed: the exit handler is registered before a
// function-local static's destructor would be, so it would run after it and read freed memory.
inline const std::filesystem::path& work_dir() {
  static const std::filesystem::path* const dir = [] {
    const auto* d =
        new std::filesystem::path(std::filesystem::temp_directory_path() / ("demoplan-fuzz-" + std::to_string(getpid())));
    std::filesystem::create_directories(*d);
    std::atexit([] {
      std::error_code ec;
      std::filesystem::remove_all(work_dir(), ec);
    });
    return d;
  }();
  return *dir;
}

// Writes the input to <work_dir>/<name> (the name's extension selects the reader for some
// loaders) and returns its path.
inline std::string write_input(const uint8_t* data, size_t size, const std::string& name) {
  const std::string path = (work_dir() / name).string();
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return path;
}

// The documented error: one line, naming the file. Aborts (a finding) otherwise.
inline void check_error(const InputError& e, const std::string& file) {
  const std::string what = e.what();
  if (what.rfind(file, 0) != 0 || what.find('\n') != std::string::npos || what.find('\r') != std::string::npos) {
    std::fprintf(stderr, "InputError breaks the one-line contract (must start with %s):\n%s\n", file.c_str(),
                 what.c_str());
    std::abort();
  }
}

// Runs `load` on the input written as `name`; InputError is the expected outcome of bad input.
template <typename Load>
int run(const uint8_t* data, size_t size, const std::string& name, Load&& load) {
  const std::string file = write_input(data, size, name);
  try {
    load(file);
  } catch (const InputError& e) {
    check_error(e, file);
  }
  return 0;
}

}  // namespace demoplan::fuzz
