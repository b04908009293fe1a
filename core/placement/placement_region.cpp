#include "core/placement/placement_region.h"

#include <charconv>
#include <cmath>
#include <sstream>

#include "core/error.h"

namespace demoplan {

namespace {

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> out;
  std::stringstream in(text);
  std::string part;
  while (std::getline(in, part, separator)) out.push_back(part);
  if (!text.empty() && text.back() == separator) out.emplace_back();
  return out;
}

double number(const std::string& text, const std::string& argument, const std::string& what) {
  size_t used = 0;
  double v = 0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || !std::isfinite(v))
    throw InputError("command line", argument, what + ": '" + text + "' is not a number");
  return v;
}

// The radical inverse of i in `base`: the i-th point of the van der Corput sequence.
double radical_inverse(int i, int base) {
  double result = 0, f = 1.0 / base;
  for (; i > 0; i /= base, f /= base) result += f * (i % base);
  return result;
}

}  // namespace

Pose BasePose::pose() const {
  Pose p = Pose::Identity();
  p.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  p.translation() = Eigen::Vector3d(x, y, z);
  return p;
}

PlacementRegion parse_placement_region(const std::string& text, const std::string& argument) {
  const std::vector<std::string> parts = split(text, ',');
  if (parts.size() != 3 && parts.size() != 4)
    throw InputError("command line", argument,
                     "'" + text + "' is not x0:x1,y0:y1,yaw0:yaw1 (metres, radians; a fourth range z0:z1 optional)");
  const char* names[] = {"x", "y", "yaw", "z"};
  Range ranges[4];
  for (size_t i = 0; i < parts.size(); ++i) {
    const std::vector<std::string> ends = split(parts[i], ':');
    if (ends.size() != 2)
      throw InputError("command line", argument, std::string(names[i]) + " range '" + parts[i] + "' is not low:high");
    ranges[i] = {number(ends[0], argument, names[i]), number(ends[1], argument, names[i])};
    if (ranges[i].high < ranges[i].low)
      throw InputError("command line", argument, std::string(names[i]) + " range '" + parts[i] + "' is inverted");
    if (i < 2 && ranges[i].high == ranges[i].low)
      throw InputError("command line", argument, std::string(names[i]) + " range '" + parts[i] + "' is empty");
  }
  PlacementRegion r{ranges[0], ranges[1], ranges[2], std::nullopt};
  if (parts.size() == 4) r.z = ranges[3];
  return r;
}

std::string to_string(const PlacementRegion& r) {
  std::ostringstream out;
  auto shortest = [](double v) {  // the shortest text that reads back as v
    char buffer[32];
    return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, v).ptr);
  };
  auto range = [&](const Range& g) { return shortest(g.low) + ":" + shortest(g.high); };
  out << range(r.x) << "," << range(r.y) << "," << range(r.yaw);
  if (r.z) out << "," << range(*r.z);
  return out.str();
}


std::vector<BasePose> candidate_base_poses(const PlacementRegion& r, int samples, double default_z) {
  std::vector<BasePose> out;
  auto lerp = [](const Range& range, double s) { return range.low + s * (range.high - range.low); };
  for (int i = 1; i <= samples; ++i) {  // index 0 would be the region's corner
    BasePose p;
    p.x = lerp(r.x, radical_inverse(i, 2));
    p.y = lerp(r.y, radical_inverse(i, 3));
    p.yaw = lerp(r.yaw, radical_inverse(i, 5));
    p.z = r.z ? lerp(*r.z, radical_inverse(i, 7)) : default_z;
    out.push_back(p);
  }
  return out;
}

}  // namespace demoplan
