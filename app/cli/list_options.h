#pragma once
// Parsing of list-valued options shared by the benchmark subcommands: "a,b,c" and "0-4" / "1,3,7",
// and the shard "I/N" of a job spread over a cluster.
#include <string>
#include <utility>
#include <vector>

namespace demoplan::cli {

// The non-empty comma-separated items of `s`.
std::vector<std::string> split_list(const std::string& s);
// "0-4" or "1,3,7" or "2"; throws InputError naming `option` for anything else.
std::vector<int> int_range(const std::string& s, const std::string& option);
// --shard "I/N" with 1 <= I <= N, as (I, N); throws InputError naming --shard for anything else.
std::pair<int, int> parse_shard(const std::string& text);

}  // namespace demoplan::cli
