// demoplan-cli markers: the part markers to print at true scale, from the marker scene that
// `extract` reads or from a cell (its own markers, else the ones `synth --cell` puts on each face
// of a part's box, written as a marker scene with --write-scene) (issue 15).
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "app/cli/command.h"
#include "app/cli/video_commands.h"
#include "core/error.h"
#include "perception/printing/marker_sheet.h"
#include "perception/printing/printed_page.h"
#include "perception/synthetic/synthetic_video.h"

namespace demoplan::cli {

namespace {

namespace fs = std::filesystem;

struct MarkersOptions {
  std::string scene, cell, out, write_scene, paper = "a4", data_dir;
  double dpi = 300;
  bool json = false;
};

// Page k of n: OUT itself for a single page, else OUT's stem with -1, -2, ... before ".png".
std::string page_file(const std::string& out, size_t k, size_t n) {
  if (n == 1) return out;
  const fs::path p(out);
  return (p.parent_path() / (p.stem().string() + "-" + std::to_string(k + 1) + p.extension().string())).string();
}

int run_markers(const MarkersOptions& o) {
  if (o.scene.empty() == o.cell.empty()) throw InputError(o.out, "", "give a marker scene file or --cell, one of them");
  if (!o.write_scene.empty() && o.cell.empty()) throw InputError(o.write_scene, "--write-scene", "needs --cell");
  if (fs::path(o.out).extension() != ".png") throw InputError(o.out, "--out", "the pages are written as PNG: name a .png file");
  const std::string source = o.scene.empty() ? o.cell : o.scene;
  perception::MarkerScene scene =
      o.scene.empty() ? perception::cell_marker_scene(o.cell, o.data_dir) : perception::load_marker_scene(o.scene);
  perception::MarkerSheetOptions options;
  options.dpi = o.dpi;
  options.paper = perception::paper_by_name(o.paper);
  options.title = "Part markers of " + fs::path(source).filename().string();
  const auto pages = perception::marker_sheets(scene, source, options);
  nlohmann::json files = nlohmann::json::array();
  size_t count = 0;
  for (size_t k = 0; k < pages.size(); ++k) {
    const std::string file = page_file(o.out, k, pages.size());
    perception::save_png_at_dpi(file, pages[k].image, o.dpi);
    files.push_back(file);
    count += pages[k].markers.size();
  }
  if (!o.write_scene.empty()) {
    scene.cell = fs::relative(fs::absolute(o.cell), fs::absolute(o.write_scene).parent_path()).string();
    perception::save_marker_scene(o.write_scene, scene);
  }
  std::cerr << count << " markers of " << scene.objects.size() << " parts (" << scene.dictionary << ") on "
            << pages.size() << " " << o.paper << " page(s) at " << o.dpi << " dpi:\n";
  for (const auto& page : pages)
    for (const auto& m : page.markers)
      std::cerr << "  id " << m.id << "  " << std::round(m.size * 1e4) / 10 << " mm  " << m.object << "\n";
  for (const auto& f : files) std::cerr << "  page " << f.get<std::string>() << "\n";
  std::cerr << "print at 100 % and check the 50 mm scale bar\n";
  if (!o.write_scene.empty()) std::cerr << "  marker scene " << o.write_scene << " (for extract --scene)\n";
  if (o.json) {
    nlohmann::json markers = nlohmann::json::array();
    for (size_t k = 0; k < pages.size(); ++k)
      for (const auto& m : pages[k].markers)
        markers.push_back({{"id", m.id}, {"part", m.object}, {"size_mm", std::round(m.size * 1e4) / 10}, {"page", k + 1}});
    nlohmann::json j{{"pages", files}, {"markers", markers}, {"dictionary", scene.dictionary}, {"dpi", o.dpi}, {"paper", o.paper}};
    if (!o.write_scene.empty()) j["scene"] = o.write_scene;
    std::cout << j.dump() << std::endl;
  }
  return kOk;
}

}  // namespace

Command register_markers_command(CLI::App& app) {
  auto o = std::make_shared<MarkersOptions>();
  CLI::App* sub = add_video_subcommand(app, "markers");
  sub->add_option("scene", o->scene, "marker scene (demoplan-marker-scene JSON, as extract reads it)");
  sub->add_option("--cell", o->cell, "a cell: its parts' own markers, else one on each face of each part's box");
  sub->add_option("--out", o->out, "page to write (PNG; more pages as NAME-1.png, NAME-2.png, ...)")->required();
  sub->add_option("--write-scene", o->write_scene, "with --cell: also write the marker scene for extract --scene");
  sub->add_option("--paper", o->paper, "paper size")->check(CLI::IsMember({"a4", "a3", "letter"}))->capture_default_str();
  sub->add_option("--dpi", o->dpi, "resolution of the pages")->check(CLI::Range(50.0, 1200.0))->capture_default_str();
  sub->add_flag("--json", o->json, "print one JSON object on stdout");
  add_data_dir_option(*sub, o->data_dir);
  return {sub, [o] { return run_markers(*o); }};
}

}  // namespace demoplan::cli
