#pragma once
// A CLI test suite: one scratch folder for the suite, removed after it, and `run` pointing
// demoplan-cli at the bundled benchmark data (DEMOPLAN_DATA_DIR).
#include <gtest/gtest.h>

#include "tests/app/cli_runner.h"

namespace demoplan::testing_support {

class CliSuite : public ::testing::Test {
protected:
  static void SetUpTestSuite() { dir_ = make_temp_dir("demoplan_test_cli_"); }
  static void TearDownTestSuite() {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  static CliResult run(std::vector<std::string> args) {
    args.insert(args.end(), {"--data-dir", DEMOPLAN_DATA_DIR});
    return run_cli(args, dir_);
  }
  static inline fs::path dir_;
};

}  // namespace demoplan::testing_support
