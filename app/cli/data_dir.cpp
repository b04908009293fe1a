#include "app/cli/command.h"
#include "app/common/data_dir.h"

namespace demoplan::cli {

std::string default_data_dir() { return app::default_data_dir(); }

void add_data_dir_option(CLI::App& sub, std::string& data_dir) {
  data_dir = default_data_dir();
  sub.add_option("--data-dir", data_dir, "benchmark-format data folder (default: the bundled one)")
      ->check(CLI::ExistingDirectory);
}

}  // namespace demoplan::cli
