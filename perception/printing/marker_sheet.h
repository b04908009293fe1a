#pragma once
// Printable sheets of the ArUco markers stuck on parts: each marker at true size inside its white
// quiet zone (one cell wide, which detection needs) and a thin cutting frame, with its id, size,
// part and face written under it; pages of a paper size with a title and a 50 mm scale bar.
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "perception/markers/marker_scene.h"

namespace demoplan::perception {

struct Paper {
  std::string name = "a4";
  double width_mm = 210, height_mm = 297;
};
// "a4", "a3" or "letter"; throws InputError naming `field` for another name.
Paper paper_by_name(const std::string& name, const std::string& field = "--paper");

struct MarkerSheetOptions {
  double dpi = 300;
  Paper paper;
  std::string title;  // first line of every page, e.g. the scene file's name
};

struct PrintedMarker {
  std::string object;
  int id = 0;
  double size = 0;  // m, black square side
  cv::Rect square;  // the black square on the page, pixels
};
struct MarkerSheetPage {
  cv::Mat image;  // 8-bit grey
  std::vector<PrintedMarker> markers;
};

// Every marker of `scene` on as few pages as the rows need. Throws InputError naming `file` and
// the field when the scene has no marker or a marker (with its quiet zone) does not fit on the
// paper.
std::vector<MarkerSheetPage> marker_sheets(const MarkerScene& scene, const std::string& file,
                                           const MarkerSheetOptions& options = {});

// Where a marker sits on its part, in words: "+x face, top to +z" for one on an axis-aligned face
// of the part frame; "" when it faces no axis.
std::string marker_placement(const ObjectMarker& marker);

}  // namespace demoplan::perception
