#include "perception/markers/edge_refinement.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/statistics.h"

namespace demoplan::perception {

namespace {

double sample(const cv::Mat& g, double x, double y) {
  const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
  if (x0 < 0 || y0 < 0 || x0 + 1 >= g.cols || y0 + 1 >= g.rows) return -1.0;
  const double ax = x - x0, ay = y - y0;
  const uchar* r0 = g.ptr<uchar>(y0);
  const uchar* r1 = g.ptr<uchar>(y0 + 1);
  return (1 - ay) * ((1 - ax) * r0[x0] + ax * r0[x0 + 1]) + ay * ((1 - ax) * r1[x0] + ax * r1[x0 + 1]);
}

struct Line {
  cv::Point2d point, direction;
};

bool fit_line(const std::vector<cv::Point2d>& pts, Line& line) {
  if (pts.size() < 3) return false;
  cv::Point2d m(0, 0);
  for (const auto& p : pts) m += p;
  m /= static_cast<double>(pts.size());
  double sxx = 0, sxy = 0, syy = 0;
  for (const auto& p : pts) {
    const cv::Point2d d = p - m;
    sxx += d.x * d.x, sxy += d.x * d.y, syy += d.y * d.y;
  }
  const double angle = 0.5 * std::atan2(2 * sxy, sxx - syy);
  line = {m, {std::cos(angle), std::sin(angle)}};
  return true;
}

bool intersect(const Line& a, const Line& b, cv::Point2d& out) {
  const double det = a.direction.x * b.direction.y - a.direction.y * b.direction.x;
  if (std::abs(det) < 1e-6) return false;
  const cv::Point2d d = b.point - a.point;
  const double t = (d.x * b.direction.y - d.y * b.direction.x) / det;
  out = a.point + t * a.direction;
  return true;
}

}  // namespace

bool refine_corners_on_edges(const cv::Mat& grey, std::array<cv::Point2f, 4>& corners, int cells) {
  cv::Point2d centre(0, 0);
  for (const auto& c : corners) centre += cv::Point2d(c);
  centre /= 4.0;
  std::array<Line, 4> lines;
  double shortest = 1e9;
  for (int k = 0; k < 4; ++k) shortest = std::min(shortest, cv::norm(corners[(k + 1) % 4] - corners[k]));
  // Profiles reach at most into the black border cell and the white margin, never the bits.
  const double reach = std::min(3.0, 0.6 * shortest / cells);
  if (reach < 1.0) return false;
  for (int k = 0; k < 4; ++k) {
    const cv::Point2d p0(corners[k]), p1(corners[(k + 1) % 4]);
    const double len = cv::norm(p1 - p0);
    const cv::Point2d dir = (p1 - p0) / len;
    cv::Point2d normal(-dir.y, dir.x);
    if (normal.dot((p0 + p1) / 2 - centre) < 0) normal = -normal;  // outwards
    std::vector<cv::Point2d> edge;
    const int n = std::max(6, static_cast<int>(len / 1.5));
    for (int i = 0; i < n; ++i) {
      const double t = 0.15 + 0.7 * i / (n - 1);
      const cv::Point2d q = p0 + t * (p1 - p0);
      std::vector<double> profile;
      for (double s = -reach; s <= reach + 1e-9; s += 0.25) profile.push_back(sample(grey, q.x + s * normal.x, q.y + s * normal.y));
      if (std::any_of(profile.begin(), profile.end(), [](double v) { return v < 0; })) continue;
      const int m = static_cast<int>(profile.size()), k4 = std::max(1, m / 6);
      double inside = 0, outside = 0;
      for (int j = 0; j < k4; ++j) inside += profile[j], outside += profile[m - 1 - j];
      inside /= k4, outside /= k4;
      if (outside - inside < 20) continue;  // no contrast: occluded or blurred away
      const double mid = 0.5 * (inside + outside);
      // The crossing nearest the predicted edge.
      double best = 1e9, s_best = 0;
      for (int j = 0; j + 1 < m; ++j) {
        const double a = profile[j] - mid, b = profile[j + 1] - mid;
        if ((a <= 0 && b > 0) || (a < 0 && b >= 0)) {
          const double s = -reach + 0.25 * (j + a / (a - b));
          if (std::abs(s) < std::abs(best)) best = s, s_best = s;
        }
      }
      if (best > 1e8) continue;
      edge.push_back(q + s_best * normal);
    }
    // A side partly hidden bends off the line: fit, drop the points off it, fit again, and
    // require most of the side to be on it.
    if (!fit_line(edge, lines[k])) return false;
    std::vector<double> residual;
    for (const auto& p : edge) {
      const cv::Point2d d = p - lines[k].point;
      residual.push_back(std::abs(d.x * lines[k].direction.y - d.y * lines[k].direction.x));
    }
    // Off the line: farther than 3 robust standard deviations of the noise (0.35 px at least).
    const double band = std::max(0.35, 3.0 * 1.4826 * order_statistic(residual, residual.size() / 2));
    std::vector<cv::Point2d> on_line;
    for (size_t i = 0; i < edge.size(); ++i)
      if (residual[i] < band) on_line.push_back(edge[i]);
    if (static_cast<int>(on_line.size()) < std::max(4, (7 * n) / 10) || !fit_line(on_line, lines[k])) return false;
  }
  std::array<cv::Point2f, 4> refined;
  for (int k = 0; k < 4; ++k) {
    cv::Point2d c;
    if (!intersect(lines[(k + 3) % 4], lines[k], c)) return false;
    if (cv::norm(c - cv::Point2d(corners[k])) > std::max(2.0, 0.2 * shortest)) return false;
    refined[k] = cv::Point2f(static_cast<float>(c.x), static_cast<float>(c.y));
  }
  corners = refined;
  return true;
}

}  // namespace demoplan::perception
