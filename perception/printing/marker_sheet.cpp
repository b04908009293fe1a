#include "perception/printing/marker_sheet.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <opencv2/aruco.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.h"
#include "perception/markers/marker_dictionary.h"
#include "perception/printing/printed_page.h"

namespace demoplan::perception {

namespace {

constexpr double kMarginMm = 10, kGapMm = 4, kCaptionCapMm = 2.2, kTitleCapMm = 3.5;

std::string axis_name(const Eigen::Vector3d& v) {
  int axis = 0;
  v.cwiseAbs().maxCoeff(&axis);
  if (std::abs(v[axis]) < 0.97) return "";  // within 14 degrees of an axis
  return std::string(v[axis] > 0 ? "+" : "-") + "xyz"[axis];
}

std::string mm(double metres) {
  std::ostringstream s;
  s << std::round(metres * 1e4) / 10;
  return s.str();
}

struct Tile {
  size_t object = 0, marker = 0;
  int square_px = 0, quiet_px = 0;
  std::string line1, line2;
  cv::Size size;  // the whole tile: frame and caption
};

}  // namespace

Paper paper_by_name(const std::string& name, const std::string& field) {
  if (name == "a4") return {"a4", 210, 297};
  if (name == "a3") return {"a3", 297, 420};
  if (name == "letter") return {"letter", 215.9, 279.4};
  throw InputError("", field, "unknown paper '" + name + "' (a4, a3 or letter)");
}

std::string marker_placement(const ObjectMarker& m) {
  const std::string face = axis_name(m.object_T_marker.linear().col(2));
  const std::string up = axis_name(m.object_T_marker.linear().col(1));
  if (face.empty()) return "";
  return face + " face" + (up.empty() ? "" : ", top to " + up);
}

std::vector<MarkerSheetPage> marker_sheets(const MarkerScene& scene, const std::string& file,
                                           const MarkerSheetOptions& o) {
  const double px_per_mm = o.dpi / 25.4;
  const auto dictionary = marker_dictionary(scene.dictionary);
  const int cells = dictionary->markerSize + 2;
  const PageFont caption = page_font(px_per_mm, kCaptionCapMm), title = page_font(px_per_mm, kTitleCapMm);
  const int caption_line = static_cast<int>(std::lround(kCaptionCapMm * 1.8 * px_per_mm));
  const int page_w = static_cast<int>(std::lround(o.paper.width_mm * px_per_mm));
  const int page_h = static_cast<int>(std::lround(o.paper.height_mm * px_per_mm));
  const int margin = static_cast<int>(std::lround(kMarginMm * px_per_mm));
  const int gap = static_cast<int>(std::lround(kGapMm * px_per_mm));
  const int header = static_cast<int>(std::lround(kTitleCapMm * 3 * px_per_mm));
  const int footer = static_cast<int>(std::lround(12 * px_per_mm));
  const int usable_w = page_w - 2 * margin, usable_h = page_h - 2 * margin - header - footer;

  std::vector<Tile> tiles;
  for (size_t i = 0; i < scene.objects.size(); ++i)
    for (size_t j = 0; j < scene.objects[i].markers.size(); ++j) {
      const ObjectMarker& m = scene.objects[i].markers[j];
      Tile t;
      t.object = i, t.marker = j;
      t.square_px = static_cast<int>(std::lround(m.size * 1000 * px_per_mm));
      t.quiet_px = std::max(2, static_cast<int>(std::lround(t.square_px / double(cells))));
      t.line1 = "id " + std::to_string(m.id) + "  " + mm(m.size) + " mm";
      const std::string where = marker_placement(m);
      t.line2 = scene.objects[i].id + (where.empty() ? "" : ", " + where);
      const int framed = t.square_px + 2 * t.quiet_px;
      const int text_w = std::max(page_text_size(t.line1, caption).width, page_text_size(t.line2, caption).width);
      t.size = {std::max(framed, text_w), framed + 2 * caption_line + caption_line / 3};
      const std::string field = "objects[" + std::to_string(i) + "].markers[" + std::to_string(j) + "].size";
      if (t.square_px < cells * 2)
        throw InputError(file, field, "marker " + std::to_string(m.id) + " is too small to print at " + std::to_string(std::lround(o.dpi)) + " dpi");
      if (m.id < 0 || m.id >= dictionary->bytesList.rows)
        throw InputError(file, field.substr(0, field.size() - 4) + "id",
                         "marker id " + std::to_string(m.id) + " is not in " + scene.dictionary);
      if (framed > usable_w || t.size.height > usable_h)
        throw InputError(file, field,
                         "marker " + std::to_string(m.id) + " (" + mm(m.size) + " mm and its white border) does not fit on " +
                             o.paper.name + " paper: choose a larger --paper");
      tiles.push_back(std::move(t));
    }
  if (tiles.empty()) throw InputError(file, "objects", "no part carries a marker: there is nothing to print");

  // Rows left to right, pages top to bottom.
  struct Placed {
    size_t tile;
    int page;
    cv::Point at;
  };
  std::vector<Placed> placed;
  int page = 0, x = 0, y = 0, row_h = 0;
  for (size_t k = 0; k < tiles.size(); ++k) {
    const cv::Size s = tiles[k].size;
    if (x > 0 && x + s.width > usable_w) x = 0, y += row_h + gap, row_h = 0;
    if (y + s.height > usable_h) ++page, x = 0, y = 0, row_h = 0;
    placed.push_back({k, page, {margin + x, margin + header + y}});
    x += s.width + gap;
    row_h = std::max(row_h, s.height);
  }

  const int pages = page + 1;
  std::vector<MarkerSheetPage> out(static_cast<size_t>(pages));
  for (int p = 0; p < pages; ++p) {
    cv::Mat& img = out[static_cast<size_t>(p)].image;
    img = cv::Mat(page_h, page_w, CV_8UC1, cv::Scalar(255));
    std::string head = (o.title.empty() ? std::string("Part markers") : o.title) + "  -  " + scene.dictionary;
    if (pages > 1) head += "  -  page " + std::to_string(p + 1) + " of " + std::to_string(pages);
    put_page_text(img, head, {margin, margin + page_text_size("H", title).height}, title);
    put_page_text(img, "Print at 100 %, check the scale bar; cut along the grey frames, keep the white border.",
                  {margin, page_h - margin - footer + static_cast<int>(4 * px_per_mm)}, caption);
    draw_scale_bar(img, {margin, page_h - margin - static_cast<int>(6 * px_per_mm)}, px_per_mm, caption);
  }
  for (const Placed& pl : placed) {
    const Tile& t = tiles[pl.tile];
    const ObjectMarker& m = scene.objects[t.object].markers[t.marker];
    MarkerSheetPage& pg = out[static_cast<size_t>(pl.page)];
    const int framed = t.square_px + 2 * t.quiet_px;
    const cv::Rect frame(pl.at, cv::Size(framed, framed));
    cv::rectangle(pg.image, frame, cv::Scalar(170), 1);
    cv::Mat square;
    cv::aruco::drawMarker(dictionary, m.id, t.square_px, square, 1);
    const cv::Rect at(pl.at + cv::Point(t.quiet_px, t.quiet_px), square.size());
    square.copyTo(pg.image(at));
    const int text_y = pl.at.y + framed + caption_line;
    put_page_text(pg.image, t.line1, {pl.at.x, text_y}, caption);
    put_page_text(pg.image, t.line2, {pl.at.x, text_y + caption_line}, caption);
    pg.markers.push_back({scene.objects[t.object].id, m.id, m.size, at});
  }
  return out;
}

}  // namespace demoplan::perception
