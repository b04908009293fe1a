// demoplan-cli grasps: the handles generated for a cell's part and its robot's gripper (issue
// 15), the best first; --write stores them in the cell file, where the operator can edit them.
#include <iomanip>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "app/cli/command.h"
#include "core/cell/cell_scene.h"
#include "core/error.h"
#include "core/part/resting_placements.h"

namespace demoplan::cli {

namespace {

struct GraspsOptions {
  std::string cell;
  std::string part;
  std::string data_dir;
  bool write = false;
  bool json = false;
};

int run_grasps(const GraspsOptions& o) {
  Cell cell = load_cell(o.cell);
  const int index = cell.part_index(o.part);
  if (index < 0) {
    std::string known;
    for (const auto& p : cell.parts) known += (known.empty() ? "" : ", ") + p.name;
    throw InputError(o.cell, "parts", "no part '" + o.part + "' (the cell has: " + known + ")");
  }
  // Generate for this part only: the others keep what they have.
  Cell one = cell;
  one.parts = {cell.parts[index]};
  one.parts[0].auto_handles = true;
  CellSceneReport report;
  const Scene scene = build_cell_scene(one, {.data_dir = o.data_dir}, &report);
  const CellPartReport& r = report.parts.front();
  const GraspReport& g = r.grasps;
  std::cerr << o.part << " for " << scene.robot.name << "'s gripper: " << g.handles.size() << " handles from "
            << g.candidates << " grasps (" << g.fitting_lines << " of " << g.closing_lines << " closing lines fit, "
            << g.hand_checks << " hand poses checked) in " << static_cast<int>(g.seconds * 1000) << " ms; "
            << r.placements << " resting placements\n";
  nlohmann::json handles = nlohmann::json::array();
  for (const auto& h : g.handles) {
    const Eigen::Vector3d t = h.frame.pose.translation() * 1000;
    std::cerr << "  " << std::left << std::setw(18) << h.frame.name << std::right << std::fixed << std::setprecision(2)
              << " quality " << h.quality << "  width " << std::setprecision(1) << h.width * 1000 << " mm  at ("
              << t.x() << ", " << t.y() << ", " << t.z() << ") mm\n"
              << std::defaultfloat;
    nlohmann::json pose = nlohmann::json::array();
    for (int row = 0; row < 4; ++row) {
      nlohmann::json line = nlohmann::json::array();
      for (int c = 0; c < 4; ++c) line.push_back(h.frame.pose.matrix()(row, c));
      pose.push_back(line);
    }
    handles.push_back({{"name", h.frame.name}, {"pose", pose}, {"quality", h.quality}, {"width_m", h.width},
                       {"clearance", h.frame.clearance}});
  }
  if (o.write) {
    CellPart& part = cell.parts[index];
    part.auto_handles = false;
    part.handles.clear();
    for (const auto& h : g.handles) part.handles.push_back(h.frame);
    save_cell(o.cell, cell);
    std::cerr << "  written to " << o.cell << "\n";
  }
  if (o.json)
    std::cout << nlohmann::json{{"cell", o.cell},
                                {"part", o.part},
                                {"handles", handles},
                                {"placements", r.placements},
                                {"closing_lines", g.closing_lines},
                                {"fitting_lines", g.fitting_lines},
                                {"hand_checks", g.hand_checks},
                                {"seconds", g.seconds}}
                     .dump()
              << std::endl;
  return kOk;
}

}  // namespace

Command register_grasps_command(CLI::App& app) {
  auto o = std::make_shared<GraspsOptions>();
  CLI::App* sub = app.add_subcommand("grasps", "generate a cell part's grasp handles for the robot's gripper");
  sub->add_option("--cell", o->cell, "the cell file (docs/cell.md)")->required();
  sub->add_option("--part", o->part, "the part's name in the cell")->required();
  sub->add_flag("--write", o->write, "store the handles in the cell file (they are then the part's own, editable)");
  sub->add_flag("--json", o->json, "print one JSON object on stdout");
  add_data_dir_option(*sub, o->data_dir);
  return {sub, [o] { return run_grasps(*o); }};
}

}  // namespace demoplan::cli
