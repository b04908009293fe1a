#include <iostream>

#include "app/cli/command.h"
#include "core/error.h"

namespace demoplan::cli {

int run_command_line(CLI::App& app, const std::vector<Command>& commands, int argc, char** argv) {
  app.require_subcommand(1);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "error: " << e.what() << " (see --help)\n";  // one line, as every bad input
    return kBadInput;
  }
  try {
    for (const auto& c : commands)
      if (c.sub->parsed()) return c.run();
  } catch (const demoplan::InputError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kBadInput;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kFailed;
  }
  return kBadInput;
}

}  // namespace demoplan::cli
