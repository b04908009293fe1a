#include "core/io/shards.h"

#include "core/error.h"

namespace demoplan {

std::vector<int> shard_indices(int count, int shard, int shards) {
  if (shards < 1 || shard < 1 || shard > shards)
    throw InputError("command line", "--shard",
                     std::to_string(shard) + "/" + std::to_string(shards) + " is not I/N with 1 <= I <= N");
  std::vector<int> out;
  for (int i = shard - 1; i < count; i += shards) out.push_back(i);
  return out;
}

ShardHeader read_shard_header(const JsonField& root, const std::string& count_key) {
  ShardHeader h;
  h.arguments = root["arguments"].value();
  h.items = root[count_key].integer();
  if (h.items < 0) root[count_key].fail("must not be negative");
  h.shard = root["shard"]["index"].integer();
  h.shards = root["shard"]["count"].integer();
  if (h.shards < 1 || h.shard < 1 || h.shard > h.shards) root["shard"].fail("index must be within 1..count");
  return h;
}

void write_shard_header(nlohmann::json& file, const ShardHeader& h, const std::string& count_key) {
  file["arguments"] = h.arguments;
  file[count_key] = h.items;
  file["shard"] = {{"index", h.shard}, {"count", h.shards}};
}

int item_index(const JsonField& index, int items) {
  const int i = index.integer();
  if (i < 0 || i >= items) index.fail("must be within 0.." + std::to_string(items - 1));
  return i;
}

void ShardJoin::add(const std::string& file, const ShardHeader& h) {
  if (files_.empty()) {
    first_ = h;
  } else if (h.arguments != first_.arguments || h.items != first_.items || h.shards != first_.shards) {
    throw InputError(file, h.arguments != first_.arguments ? "arguments" : "shard",
                     "is from another " + kind_ + " than " + files_.begin()->second +
                         " (different arguments or shard count)");
  }
  if (files_.count(h.shard))
    throw InputError(file, "shard", "shard " + std::to_string(h.shard) + " is also in " + files_[h.shard]);
  files_[h.shard] = file;
}

void ShardJoin::claim(const std::string& file, int index, const std::string& field) {
  if (!claimed_.emplace(index, file).second)
    throw InputError(file, field, "item " + std::to_string(index) + " is also in " + claimed_[index]);
}

void ShardJoin::finish(const std::string& item_name) const {
  if (files_.empty()) throw InputError("command line", "files", "no partial results given");
  const std::string& first = files_.begin()->second;
  for (int s = 1; s <= first_.shards; ++s)
    if (!files_.count(s))
      throw InputError(first, "shard", "shard " + std::to_string(s) + " of " + std::to_string(first_.shards) + " is missing");
  if (static_cast<int>(claimed_.size()) != first_.items)
    throw InputError(first, item_name, std::to_string(claimed_.size()) + " of " + std::to_string(first_.items) + " " +
                                           item_name + " in the shards");
}

}  // namespace demoplan
