// demoplan-cli merge: joins the partial results of a placement search run as shards (a Slurm
// job array) into the ranking one unsharded run gives.
#include <iostream>
#include <memory>

#include "app/cli/command.h"
#include "app/cli/placement_summary.h"
#include "core/placement/placement_result.h"

namespace demoplan::cli {

namespace {

struct MergeOptions {
  std::vector<std::string> files;
  std::string out, heat_map;
  bool json = false;
};

int run_merge(const MergeOptions& o) {
  const PlacementResult merged = merge_placement_results(o.files);
  save_placement_result(o.out, merged);
  std::cerr << "merged " << o.files.size() << " shard(s) into " << o.out << "\n";
  print_placement_summary(merged);
  if (!o.heat_map.empty()) write_placement_heat_map(o.heat_map, merged);
  if (o.json) std::cout << placement_summary_json(merged, o.out).dump() << std::endl;
  return merged.message().empty() ? kOk : kFailed;
}

}  // namespace

Command register_merge_command(CLI::App& app) {
  auto opts = std::make_shared<MergeOptions>();
  CLI::App* sub = app.add_subcommand("merge", "join the shards of a placement search (place --shard I/N)");
  sub->add_option("files", opts->files, "the partial results, one per shard")->required();
  sub->add_option("--out", opts->out, "the joined result")->required();
  sub->add_option("--heat-map", opts->heat_map, "draw the region as PNG or SVG");
  sub->add_flag("--json", opts->json, "print one JSON object on stdout");
  return {sub, [opts] { return run_merge(*opts); }};
}

}  // namespace demoplan::cli
