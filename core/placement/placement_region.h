#pragma once
// Where a robot's base may stand, as the placement search takes it: ranges of x, y and yaw (and,
// for a fixed robot's pedestal, z), and the candidate base poses spread over them.
#include <optional>
#include <string>
#include <vector>

#include "core/geometry/se3.h"

namespace demoplan {

struct Range {
  double low = 0, high = 0;
};

struct PlacementRegion {
  Range x, y;               // m, world
  Range yaw;                // rad, about the world z axis
  std::optional<Range> z;   // m; absent: the base height of the reference pose
};

struct BasePose {
  double x = 0, y = 0, z = 0, yaw = 0;
  Pose pose() const;  // translation (x, y, z), rotation yaw about z
  bool operator==(const BasePose&) const = default;
};

// "x0:x1,y0:y1,yaw0:yaw1[,z0:z1]" (m, m, rad, m). Throws InputError("command line", argument, ...)
// naming the range that is malformed, empty (x, y) or inverted.
PlacementRegion parse_placement_region(const std::string& text, const std::string& argument = "--region");
std::string to_string(const PlacementRegion& region);

// `samples` base poses on a Halton sequence (bases 2, 3, 5, 7): spread evenly over the region,
// any prefix as even as the whole, the same for the same arguments on every machine.
std::vector<BasePose> candidate_base_poses(const PlacementRegion& region, int samples, double default_z);

}  // namespace demoplan
