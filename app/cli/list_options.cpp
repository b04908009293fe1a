#include "app/cli/list_options.h"

#include <sstream>

#include "core/error.h"

namespace demoplan::cli {

std::vector<std::string> split_list(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

std::vector<int> int_range(const std::string& s, const std::string& option) {
  std::vector<int> out;
  for (const auto& part : split_list(s)) {
    try {
      const auto dash = part.find('-');
      if (dash == std::string::npos) {
        out.push_back(std::stoi(part));
      } else {
        const int a = std::stoi(part.substr(0, dash)), b = std::stoi(part.substr(dash + 1));
        for (int i = a; i <= b; ++i) out.push_back(i);
      }
    } catch (const std::exception&) {
      throw InputError("command line", option, "'" + part + "' is not a number or range like 0-4");
    }
  }
  return out;
}

}  // namespace demoplan::cli
