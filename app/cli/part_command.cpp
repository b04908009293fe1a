// demoplan-cli part: where a part rests, from its mesh alone (issue 15): the faces of its convex
// hull it stands on, the stablest first.
#include <iomanip>
#include <iostream>
#include <memory>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "app/cli/command.h"
#include "core/error.h"
#include "core/model/mesh.h"
#include "core/part/resting_placements.h"

namespace demoplan::cli {

namespace {

struct PartOptions {
  std::string mesh;
  double scale = 1.0;
  bool json = false;
  RestingPlacementOptions placements;
};

int run_part(const PartOptions& o) {
  if (!(o.scale > 0)) throw InputError(o.mesh, "--scale", "must be > 0");
  const auto mesh = load_mesh(o.mesh);
  std::vector<Eigen::Vector3d> points;
  for (const auto& v : mesh->vertices) points.push_back(v.cast<double>() * o.scale);
  const Eigen::Vector3d com = centre_of_mass(*mesh, o.scale);
  std::vector<RestingPlacement> placements;
  try {
    placements = resting_placements(points, com, o.placements);
  } catch (const std::invalid_argument& e) {
    throw InputError(o.mesh, "vertices", e.what());
  }
  const Eigen::Vector3f size = mesh->bounds().sizes() * static_cast<float>(o.scale);
  std::cerr << o.mesh << ": " << mesh->vertices.size() << " vertices, " << size.x() * 1000 << " x " << size.y() * 1000
            << " x " << size.z() * 1000 << " mm, centre of mass (" << com.x() * 1000 << ", " << com.y() * 1000 << ", "
            << com.z() * 1000 << ") mm\n"
            << placements.size() << " resting placements, the stablest first:\n";
  for (size_t k = 0; k < placements.size(); ++k) {
    const auto& p = placements[k];
    std::cerr << "  " << k << ": normal (" << std::fixed << std::setprecision(3) << p.normal.x() << ", " << p.normal.y()
              << ", " << p.normal.z() << "), " << std::setprecision(1) << p.area * 1e4 << " cm2, margin " << p.margin * 1000
              << " mm, centre " << p.height * 1000 << " mm above, tips at " << p.tipping_angle * 180 / M_PI << " deg\n"
              << std::defaultfloat;
  }
  if (o.json) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& p : placements) {
      nlohmann::json polygon = nlohmann::json::array();
      for (const auto& v : p.polygon) polygon.push_back({v.x(), v.y(), v.z()});
      nlohmann::json pose = nlohmann::json::array();
      for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) pose.push_back(p.part_on_plane.matrix()(r, c));
      list.push_back({{"normal", {p.normal.x(), p.normal.y(), p.normal.z()}},
                      {"area_m2", p.area},
                      {"margin_m", p.margin},
                      {"height_m", p.height},
                      {"tipping_angle_deg", p.tipping_angle * 180 / M_PI},
                      {"polygon", polygon},
                      {"part_on_plane", pose}});
    }
    std::cout << nlohmann::json{{"mesh", o.mesh}, {"centre_of_mass", {com.x(), com.y(), com.z()}}, {"placements", list}}.dump()
              << std::endl;
  }
  return kOk;
}

}  // namespace

Command register_part_command(CLI::App& app) {
  auto o = std::make_shared<PartOptions>();
  CLI::App* sub = app.add_subcommand("part", "where a part rests on a flat surface, from its mesh alone");
  sub->add_option("mesh", o->mesh, "the part's mesh (any file assimp reads: STL, OBJ, PLY, DAE, glTF)")->required();
  sub->add_option("--scale", o->scale, "metres per mesh unit (0.001 for a mesh in millimetres)")->capture_default_str();
  sub->add_option("--min-area", o->placements.min_area, "m^2: smaller faces are left out")->capture_default_str();
  sub->add_option("--contact-tolerance", o->placements.contact_tolerance,
                  "m: hull points this close to a face's plane touch the surface")
      ->capture_default_str();
  sub->add_flag("--json", o->json, "print one JSON object on stdout");
  return {sub, [o] { return run_part(*o); }};
}

}  // namespace demoplan::cli
