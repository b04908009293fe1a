// demoplan-cli figure as a user runs it: a small bench result (2 robots, 2 tasks, 2 planners)
// drawn to SVG (one panel per robot and metric, every planner in the legend) and PNG (its size),
// the one JSON object on stdout, and one-line errors with exit 2 naming the file and the field.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <regex>
#include <set>

#include "tests/app/cli_runner.h"

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using namespace demoplan::testing_support;

// Rows as `bench --out` writes them; a task with nothing solved has null times (NaN).
Json bench_result(const std::vector<std::string>& planners) {
  Json rows = Json::array(), runs = Json::array();
  for (const std::string robot : {"ur5", "panda"})
    for (const std::string task : {"tunnel_0", "shelf_1"}) {
      for (size_t p = 0; p < planners.size(); ++p) {
        const bool none = robot == "ur5" && task == "tunnel_0" && p == 1;
        rows.push_back({{"task", task}, {"robot", robot}, {"planner", planners[p]}, {"runs", 4},
                        {"solved", none ? 0 : 4}, {"success_rate", none ? 0.0 : 1.0 - 0.25 * double(p)},
                        {"feasible_runs", 4}, {"success_rate_feasible", 1.0},
                        {"median_time_s", none ? Json() : Json(1.5 + double(p))}, {"mean_time_s", 1.7},
                        {"median_path_length_rad", none ? Json() : Json(20.0 - 5.0 * double(p))},
                        {"mean_grasps", none ? Json() : Json(2.0)}});
      }
      for (int seed = 1; seed <= 4; ++seed)
        runs.push_back({{"task", task}, {"robot", robot}, {"pose", 0}, {"seed", seed}, {"solved", true},
                        {"valid", true}, {"message", "ok"}, {"feasible", true}, {"planning_time_s", 0.5 * seed},
                        {"iterations", 10}, {"trees", 3}, {"nodes", 100}, {"path_length_rad", 20.0},
                        {"shortened_path_length_rad", 15.0}, {"grasps", 2}});
    }
  return {{"format", "demoplan-bench"}, {"version", 1}, {"from", "subgoals"}, {"rows", rows}, {"runs", runs}};
}

size_t count(const std::string& text, const std::regex& re) {
  return static_cast<size_t>(std::distance(std::sregex_iterator(text.begin(), text.end(), re), std::sregex_iterator()));
}

// Width and height from a PNG's IHDR chunk.
std::pair<int, int> png_size(const std::string& png) {
  if (png.size() < 24 || png.compare(1, 3, "PNG") != 0) return {0, 0};
  auto be32 = [&](size_t at) {
    return (int(static_cast<unsigned char>(png[at])) << 24) | (int(static_cast<unsigned char>(png[at + 1])) << 16) |
           (int(static_cast<unsigned char>(png[at + 2])) << 8) | int(static_cast<unsigned char>(png[at + 3]));
  };
  return {be32(16), be32(20)};
}

class CliFigure : public ::testing::Test {
protected:
  void SetUp() override {
    dir_ = make_temp_dir("demoplan_test_cli_figure_");
    write_text(dir_ / "bench.json", bench_result({"guided", "guided+shortcut"}).dump(1));
  }
  void TearDown() override { fs::remove_all(dir_); }
  CliResult run(const std::vector<std::string>& args) const { return run_cli(args, dir_); }
  void expect_bad_input(const CliResult& r, const std::vector<std::string>& parts) const {
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_EQ(lines(r.err).size(), 1u) << r.err;
    for (const auto& p : parts) EXPECT_NE(r.err.find(p), std::string::npos) << "'" << p << "' not in: " << r.err;
  }
  fs::path dir_;
};

TEST_F(CliFigure, SvgHasAPanelPerRobotAndMetric) {
  const fs::path svg = dir_ / "fig4.svg";
  const CliResult r = run({"figure", (dir_ / "bench.json").string(), "--out", svg.string(), "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  ASSERT_EQ(lines(r.out).size(), 1u) << r.out;
  const Json j = Json::parse(r.out);
  EXPECT_EQ(j["out"], svg.string());
  EXPECT_EQ(j["panels"], 8);
  EXPECT_EQ(j["robots"], Json({"panda", "ur5"}));          // the paper's order, not the file's
  EXPECT_EQ(j["tasks"], Json({"shelf_1", "tunnel_0"}));
  EXPECT_EQ(j["planners"], Json({"guided", "guided+shortcut"}));
  ASSERT_TRUE(fs::exists(svg));
  const std::string text = read_text(svg);
  // XML-ish: a declaration, one <svg> root closed at the end, as many <g> opened as closed.
  EXPECT_EQ(text.rfind("<?xml", 0), 0u);
  EXPECT_EQ(count(text, std::regex("<svg ")), 1u);
  EXPECT_NE(text.find("</svg>\n", text.size() - 8), std::string::npos);
  EXPECT_EQ(count(text, std::regex("<g[ >]")), count(text, std::regex("</g>")));
  EXPECT_EQ(count(text, std::regex("<text[^>]*>[^<]*&(?!amp;|lt;|gt;|quot;|#)")), 0u);  // escaped text
  // One panel per robot and metric.
  EXPECT_EQ(count(text, std::regex("<g id=\"panel-")), 8u);
  for (const std::string robot : {"panda", "ur5"})
    for (const std::string metric : {"success_rate", "planning_time", "path_length", "grasps"})
      EXPECT_NE(text.find("id=\"panel-" + robot + "-" + metric + "\""), std::string::npos) << robot << " " << metric;
  // Titles, units, the tasks under the bars, the planners in the legend, values above bars.
  for (const std::string s : {"Success rate", "Planning time", "Path length", "Number of grasps", ">shelf_1<",
                              ">tunnel_0<", ">guided<", ">guided+shortcut<", ">Panda<", ">UR5<", ">100<", ">75<"})
    EXPECT_NE(text.find(s), std::string::npos) << s;
}

// A planner added later (another file) becomes more bars, with its own colour in the legend; the
// same planner on the raw video estimates is another planner, in another colour.
TEST_F(CliFigure, PlannersOfEveryFileBecomeBars) {
  write_text(dir_ / "ompl.json", bench_result({"ompl-rrtconnect"}).dump());
  Json raw = bench_result({"guided"});
  raw["from"] = "raw";
  write_text(dir_ / "raw.json", raw.dump());
  const CliResult r = run({"figure", (dir_ / "bench.json").string(), (dir_ / "ompl.json").string(),
                           (dir_ / "raw.json").string(), "--out", (dir_ / "fig.svg").string(), "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const Json j = Json::parse(r.out);
  EXPECT_EQ(j["planners"], Json({"guided", "guided+shortcut", "ompl-rrtconnect", "guided (raw)"}));
  const std::string text = read_text(dir_ / "fig.svg");
  const size_t at = text.find("<g id=\"legend\">");
  ASSERT_NE(at, std::string::npos);
  const std::string legend = text.substr(at, text.find("</g>", at) - at);
  std::set<std::string> fills;
  const std::regex swatch("<rect [^>]*fill=\"(#[0-9a-f]{6})\"");
  for (auto it = std::sregex_iterator(legend.begin(), legend.end(), swatch); it != std::sregex_iterator(); ++it)
    fills.insert((*it)[1]);
  EXPECT_EQ(fills.size(), 4u) << legend;  // four swatches, four colours
  // Each planner's bars have its legend colour: 2 robots x 2 tasks x 4 metrics bars per planner.
  for (const std::string& f : fills) EXPECT_GE(count(text, std::regex("fill=\"" + f + "\"")), 1u + 2 * 2 * 3) << f;
}

// A benchmark run in parts (the base poses that cannot be done apart, as in docs/bench-*.json):
// rows of the same robot, task and planner are pooled, not replaced.
TEST_F(CliFigure, RowsRunInPartsArePooled) {
  Json part = bench_result({"guided"});
  Json rows = Json::array();
  for (Json row : part["rows"])
    if (row["robot"] == "panda" && row["task"] == "shelf_1") {
      row["solved"] = 0, row["success_rate"] = 0.0, row["median_time_s"] = nullptr;
      row["median_path_length_rad"] = nullptr, row["mean_grasps"] = nullptr;
      rows.push_back(row);
    }
  part["rows"] = rows;
  part["runs"] = Json::array();
  write_text(dir_ / "part.json", part.dump());
  const CliResult r = run({"figure", (dir_ / "bench.json").string(), (dir_ / "part.json").string(), "--out",
                           (dir_ / "fig.svg").string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string text = read_text(dir_ / "fig.svg");
  const size_t panel = text.find("id=\"panel-panda-success_rate\"");
  const std::string success = text.substr(panel, text.find("</g>", panel) - panel);
  EXPECT_NE(success.find(">50<"), std::string::npos);  // 4 of 8 runs of shelf_1 with guided
  EXPECT_NE(success.find(">100<"), std::string::npos);  // tunnel_0 untouched
  // The times of the part that solved something stay.
  const size_t time_panel = text.find("id=\"panel-panda-planning_time\"");
  EXPECT_NE(text.substr(time_panel, text.find("</g>", time_panel) - time_panel).find(">1.50<"), std::string::npos);
}

TEST_F(CliFigure, PngHasTheReportedSize) {
  const fs::path png = dir_ / "fig4.png";
  const CliResult r = run({"figure", (dir_ / "bench.json").string(), "--out", png.string(), "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const Json j = Json::parse(r.out);
  const auto [w, h] = png_size(read_text(png));
  EXPECT_EQ(w, j["width"].get<int>());
  EXPECT_EQ(h, j["height"].get<int>());
  // Four panels across, two robots down, at twice the SVG's units.
  EXPECT_GE(w, 4 * 2 * 300);
  EXPECT_GE(h, 2 * 2 * 220);
  EXPECT_LT(h, w);
}

TEST_F(CliFigure, BadInputNamesTheFileAndTheField) {
  const std::string out = (dir_ / "f.svg").string();
  write_text(dir_ / "text.json", "not json at all");
  expect_bad_input(run({"figure", (dir_ / "text.json").string(), "--out", out}), {"text.json"});

  Json wrong = bench_result({"guided"});
  wrong["format"] = "demoplan-path";
  write_text(dir_ / "wrong.json", wrong.dump());
  expect_bad_input(run({"figure", (dir_ / "wrong.json").string(), "--out", out}), {"wrong.json", "format"});

  Json version = bench_result({"guided"});
  version["version"] = 7;
  write_text(dir_ / "version.json", version.dump());
  expect_bad_input(run({"figure", (dir_ / "version.json").string(), "--out", out}), {"version.json", "version"});

  Json missing = bench_result({"guided"});
  missing["rows"][1].erase("success_rate");
  write_text(dir_ / "missing.json", missing.dump());
  expect_bad_input(run({"figure", (dir_ / "missing.json").string(), "--out", out}),
                   {"missing.json", "rows[1].success_rate"});

  Json no_rows = bench_result({"guided"});
  no_rows.erase("rows");
  write_text(dir_ / "norows.json", no_rows.dump());
  expect_bad_input(run({"figure", (dir_ / "norows.json").string(), "--out", out}), {"norows.json", "rows"});

  expect_bad_input(run({"figure", (dir_ / "absent.json").string(), "--out", out}), {"absent.json"});
  expect_bad_input(run({"figure", (dir_ / "bench.json").string(), "--out", (dir_ / "f.pdf").string()}), {"--out", ".svg"});
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
