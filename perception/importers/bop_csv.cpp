#include "perception/importers/bop_csv.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.h"

namespace demoplan::perception {

namespace {

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : s) {
    if (c == sep) {
      out.push_back(cur);
      cur.clear();
    } else if (c != '\r') {
      cur += c;
    }
  }
  out.push_back(cur);
  return out;
}

std::vector<double> numbers(const std::string& s, const std::string& path, const std::string& where,
                            const std::string& field, size_t expected) {
  std::istringstream in(s);
  std::vector<double> out;
  std::string tok;
  while (in >> tok) {
    char* end = nullptr;
    const double v = std::strtod(tok.c_str(), &end);
    if (end == tok.c_str() || *end != '\0' || !std::isfinite(v))
      throw InputError(path, where, field + ": '" + tok + "' is not a finite number");
    out.push_back(v);
  }
  if (out.size() != expected)
    throw InputError(path, where, field + " must hold " + std::to_string(expected) + " numbers separated by spaces, found " +
                                      std::to_string(out.size()));
  return out;
}

int integer(const std::string& s, const std::string& path, const std::string& where, const std::string& field) {
  const std::vector<double> v = numbers(s, path, where, field, 1);
  if (v[0] != std::floor(v[0]) || v[0] < 0 || v[0] > 1e9)
    throw InputError(path, where, field + " must be a non-negative integer");
  return static_cast<int>(v[0]);
}

}  // namespace

int bop_object_id(const std::string& part_id) {
  if (part_id.rfind("YCBV_", 0) != 0) return -1;
  try {
    return std::stoi(part_id.substr(5));
  } catch (...) {
    return -1;
  }
}

std::vector<BopDetection> load_bop_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "", "cannot open the detections file");
  std::vector<BopDetection> out;
  std::string line;
  int n = 0;
  while (std::getline(in, line)) {
    ++n;
    const std::string where = "line " + std::to_string(n);
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const auto f = split(line, ',');
    if (n == 1 && f.size() >= 1 && f[0].find("scene_id") != std::string::npos) {
      if (f.size() != 7) throw InputError(path, where, "header must be scene_id,im_id,obj_id,score,R,t,time");
      continue;
    }
    if (f.size() != 7)
      throw InputError(path, where, "expected 7 comma-separated fields (scene_id,im_id,obj_id,score,R,t,time), found " +
                                        std::to_string(f.size()));
    BopDetection d;
    d.line = n;
    d.scene_id = integer(f[0], path, where, "scene_id");
    d.image_id = integer(f[1], path, where, "im_id");
    d.object_id = integer(f[2], path, where, "obj_id");
    d.score = numbers(f[3], path, where, "score", 1)[0];
    const auto R = numbers(f[4], path, where, "R", 9);
    const auto t = numbers(f[5], path, where, "t", 3);
    d.time = numbers(f[6], path, where, "time", 1)[0];
    Eigen::Matrix3d M;
    M << R[0], R[1], R[2], R[3], R[4], R[5], R[6], R[7], R[8];
    if (!is_rotation(M, 1e-3)) throw InputError(path, where, "R is not a rotation matrix (orthonormal, det +1)");
    // Re-orthonormalise what the writer's rounding left.
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
    d.camera_T_object.linear() = svd.matrixU() * svd.matrixV().transpose();
    d.camera_T_object.translation() << t[0] / 1000.0, t[1] / 1000.0, t[2] / 1000.0;
    out.push_back(d);
  }
  return out;
}

void save_bop_csv(const std::string& path, const std::vector<BopDetection>& detections) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::trunc);
    if (!out) throw InputError(path, "", "cannot write file");
    out << "scene_id,im_id,obj_id,score,R,t,time\n";
    char buf[64];
    for (const auto& d : detections) {
      out << d.scene_id << ',' << d.image_id << ',' << d.object_id << ',' << d.score << ',';
      for (int i = 0; i < 9; ++i) {
        std::snprintf(buf, sizeof buf, "%.9g", d.camera_T_object.linear()(i / 3, i % 3));
        out << (i ? " " : "") << buf;
      }
      out << ',';
      for (int i = 0; i < 3; ++i) {
        std::snprintf(buf, sizeof buf, "%.6f", d.camera_T_object.translation()[i] * 1000.0);
        out << (i ? " " : "") << buf;
      }
      out << ',' << d.time << '\n';
    }
    if (!out) throw InputError(path, "", "write failed");
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) throw InputError(path, "", "cannot replace file: " + ec.message());
}

}  // namespace demoplan::perception
