// demoplan-cli merge: joins the partial results of a job run as shards (a Slurm job array) into
// the result one unsharded run gives: a placement search (place --shard I/N) or a benchmark
// (bench --shard I/N), told apart by the files' "format".
#include <iostream>
#include <memory>

#include "app/cli/bench_file.h"
#include "app/cli/command.h"
#include "app/cli/placement_summary.h"
#include "core/error.h"
#include "core/io/json_file.h"
#include "core/placement/placement_result.h"

namespace demoplan::cli {

namespace {

constexpr const char* kPlacementFormat = "demoplan-placement";

struct MergeOptions {
  std::vector<std::string> files;
  std::string out, heat_map;
  bool json = false;
};

std::string format_of(const std::string& file) {
  const Json json = read_json_file(file);
  const JsonField root(json, file);
  if (!json.is_object() || !root.has("format")) root.fail("not a demoplan result: no \"format\"");
  const std::string format = root["format"].string();
  if (format != kPlacementFormat && format != kBenchFormat)
    root["format"].fail("'" + format + "' is neither a placement search's (" + kPlacementFormat +
                        ") nor a benchmark's (" + kBenchFormat + ") result");
  return format;
}

int merge_placement(const MergeOptions& o) {
  const PlacementResult merged = merge_placement_results(o.files);
  save_placement_result(o.out, merged);
  std::cerr << "merged " << o.files.size() << " shard(s) into " << o.out << "\n";
  print_placement_summary(merged);
  if (!o.heat_map.empty()) write_placement_heat_map(o.heat_map, merged);
  if (o.json) std::cout << placement_summary_json(merged, o.out).dump() << std::endl;
  return merged.message().empty() ? kOk : kFailed;
}

int merge_bench(const MergeOptions& o) {
  if (!o.heat_map.empty()) throw InputError("command line", "--heat-map", "a benchmark has no heat map");
  const BenchFile merged = merge_bench_files(o.files);
  const BenchTable table = tabulate_bench_runs(merged.runs, merged.planners());
  save_bench_file(o.out, merged, table);
  std::cerr << "merged " << o.files.size() << " shard(s), " << merged.runs.size() << " runs, into " << o.out << "\n";
  print_bench_table(table);
  if (o.json)
    std::cout << nlohmann::json{{"out", o.out}, {"runs", merged.runs.size()}, {"rows", table.rows},
                                {"comparisons", table.comparisons}}.dump()
              << std::endl;
  return kOk;
}

int run_merge(const MergeOptions& o) {
  // The first file says what is merged; the loader of that kind refuses, naming the file, any
  // other of another format as it reads it (each file is read once).
  return format_of(o.files.front()) == kBenchFormat ? merge_bench(o) : merge_placement(o);
}

}  // namespace

Command register_merge_command(CLI::App& app) {
  auto opts = std::make_shared<MergeOptions>();
  CLI::App* sub = app.add_subcommand("merge", "join the shards of a placement search or a benchmark (--shard I/N)");
  sub->add_option("files", opts->files, "the partial results, one per shard")->required();
  sub->add_option("--out", opts->out, "the joined result")->required();
  sub->add_option("--heat-map", opts->heat_map, "of a placement search: draw the region as PNG or SVG");
  sub->add_flag("--json", opts->json, "print one JSON object on stdout");
  return {sub, [opts] { return run_merge(*opts); }};
}

}  // namespace demoplan::cli
