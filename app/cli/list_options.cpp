#include "app/cli/list_options.h"

#include <sstream>

#include "core/error.h"
#include "core/io/shards.h"

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

std::pair<int, int> parse_shard(const std::string& text) {
  const auto slash = text.find('/');
  try {
    if (slash != std::string::npos) {
      size_t a = 0, b = 0;
      const int i = std::stoi(text.substr(0, slash), &a), n = std::stoi(text.substr(slash + 1), &b);
      if (a == slash && b == text.size() - slash - 1) {
        shard_indices(0, i, n);  // throws for one out of range
        return {i, n};
      }
    }
  } catch (const std::invalid_argument&) {
  } catch (const std::out_of_range&) {
  }
  throw InputError("command line", "--shard", "'" + text + "' is not I/N (e.g. 2/4)");
}

}  // namespace demoplan::cli
