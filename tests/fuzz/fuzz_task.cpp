// libFuzzer target: a benchmark task file (core/demo/benchmark_task.h, load_benchmark_task),
// read as <data>/tasks/fuzz_0.json from a data folder whose robots, objects and furniture are
// links to the bundled benchmark data, so that the files a task names can exist.
// Any input must load or throw InputError naming the file (tests/fuzz/fuzz_input.h).
#include "core/demo/benchmark_task.h"
#include "tests/fuzz/fuzz_input.h"

namespace fs = std::filesystem;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const fs::path dir = [] {
    const fs::path d = demoplan::fuzz::work_dir() / "data";
    fs::create_directories(d / "tasks");
    for (const char* sub : {"robots", "objects", "furniture"})
      fs::create_directory_symlink(fs::path(DEMOPLAN_RESOURCE_DIR "/gtamp") / sub, d / sub);
    return d;
  }();
  return demoplan::fuzz::run(data, size, "data/tasks/fuzz_0.json",
                             [](const std::string&) { demoplan::load_benchmark_task(dir.string(), "fuzz_0"); });
}
