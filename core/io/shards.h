#pragma once
// A long job split into shards (`--shard I/N`: place, bench), each writing a partial result, and
// the partial results joined again. Which items a shard does, and the checks that a set of
// partial files is exactly the shards of one job.
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/io/json_file.h"

namespace demoplan {

// The indices of 0..count-1 that shard `shard` of `shards` (1-based) does: every shards-th, so
// each shard gets a like share. Throws InputError("command line", "--shard", ...) out of range.
std::vector<int> shard_indices(int count, int shard, int shards);

// What a partial result says of the job it belongs to.
struct ShardHeader {
  nlohmann::json arguments;  // everything that defines the job's items and how they are done
  int items = 0;             // in the whole job
  int shard = 1, shards = 1;
};

// The header every partial result file carries: "arguments", `count_key` (the job's item count)
// and "shard": {"index", "count"}. Read with its ranges checked (InputError naming the field).
ShardHeader read_shard_header(const JsonField& root, const std::string& count_key);
void write_shard_header(nlohmann::json& file, const ShardHeader& header, const std::string& count_key);
// An item's index in the whole job, as a partial file gives it: within 0..items-1.
int item_index(const JsonField& index, int items);

// Collects the partial files of one job: every shard exactly once, the same arguments, item
// count and shard count, no item twice. Each check throws InputError naming the file at fault.
class ShardJoin {
public:
  explicit ShardJoin(std::string kind) : kind_(std::move(kind)) {}  // "search", "benchmark": for messages
  void add(const std::string& file, const ShardHeader& header);
  // Item `index` of the file just added; throws when another file had it.
  void claim(const std::string& file, int index, const std::string& field);
  // Throws for a missing shard or items missing in all.
  void finish(const std::string& item_name) const;
  const ShardHeader& header() const { return first_; }

private:
  std::string kind_;
  ShardHeader first_;
  std::map<int, std::string> files_;  // shard -> file
  std::map<int, std::string> claimed_;  // item -> file
};

}  // namespace demoplan
