// Printable part markers: every marker of a scene is on a page, found by OpenCV's detector with
// its id, its black square as large as the scene says at the page's DPI; the PNG records that
// DPI; too many markers spill onto more pages; a marker too large for the paper is refused with
// the scene file and the field.
#include <gtest/gtest.h>

#include <map>

#include <opencv2/aruco.hpp>
#include <opencv2/imgcodecs.hpp>

#include "core/error.h"
#include "perception/markers/marker_dictionary.h"
#include "perception/printing/marker_sheet.h"
#include "perception/printing/printed_page.h"
#include "perception/synthetic/marker_layout.h"
#include "tests/support/temp_folder.h"

using namespace demoplan;
using namespace demoplan::perception;

namespace {

MarkerScene scene_with(int parts, double size) {
  MarkerScene s;
  s.dictionary = "DICT_4X4_100";
  for (int p = 0; p < parts; ++p) {
    MarkedObject o;
    o.id = "part_" + std::to_string(p);
    o.markers = box_face_markers(Eigen::AlignedBox3d(Eigen::Vector3d(-0.05, -0.04, 0), Eigen::Vector3d(0.05, 0.04, 0.06)),
                                 p * kBoxFaceMarkers, {.max_size = size});
    s.objects.push_back(o);
  }
  return s;
}

// Every marker OpenCV finds on the pages: id -> side of its square in pixels (mean of 4 edges).
std::map<int, double> detected(const std::vector<MarkerSheetPage>& pages, const std::string& dictionary) {
  std::map<int, double> out;
  for (const auto& page : pages) {
    std::vector<std::vector<cv::Point2f>> corners;
    std::vector<int> ids;
    cv::aruco::detectMarkers(page.image, marker_dictionary(dictionary), corners, ids);
    for (size_t k = 0; k < ids.size(); ++k) {
      double side = 0;
      for (int e = 0; e < 4; ++e) side += cv::norm(corners[k][size_t(e)] - corners[k][size_t((e + 1) % 4)]) / 4;
      EXPECT_EQ(out.count(ids[k]), 0u) << "marker " << ids[k] << " printed twice";
      out[ids[k]] = side;
    }
  }
  return out;
}

}  // namespace

TEST(MarkerSheet, EveryMarkerAtTrueSize) {
  const MarkerScene scene = scene_with(2, 0.03);  // 12 markers, 30 mm and smaller
  for (double dpi : {150.0, 300.0}) {
    const auto pages = marker_sheets(scene, "scene.json", {.dpi = dpi});
    ASSERT_EQ(pages.size(), 1u) << dpi;
    EXPECT_EQ(pages[0].image.cols, std::lround(210 * dpi / 25.4));
    EXPECT_EQ(pages[0].image.rows, std::lround(297 * dpi / 25.4));
    const auto found = detected(pages, scene.dictionary);
    EXPECT_EQ(found.size(), 12u) << dpi;
    for (const auto& o : scene.objects)
      for (const auto& m : o.markers) {
        ASSERT_EQ(found.count(m.id), 1u) << "marker " << m.id << " at " << dpi << " dpi";
        // Corners are found at the squares' outer edges: the side is the printed width in pixels.
        EXPECT_NEAR(found.at(m.id), m.size * 1000 * dpi / 25.4, 1.5) << m.id << " at " << dpi << " dpi";
      }
  }
}

TEST(MarkerSheet, CaptionsSayWhereTheMarkerGoes) {
  const MarkerScene scene = scene_with(1, 0.03);
  EXPECT_EQ(marker_placement(scene.objects[0].markers[0]), "+x face, top to +z");
  EXPECT_EQ(marker_placement(scene.objects[0].markers[5]), "-z face, top to +x");
  ObjectMarker tilted;
  tilted.object_T_marker.linear() = Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitX()).toRotationMatrix();
  EXPECT_EQ(marker_placement(tilted), "");
}

TEST(MarkerSheet, ManyMarkersSpillOntoMorePages) {
  const MarkerScene scene = scene_with(6, 0.06);  // 36 markers of up to 60 mm: more than an A4 page
  const auto pages = marker_sheets(scene, "scene.json", {.dpi = 100});
  EXPECT_GE(pages.size(), 2u);
  size_t listed = 0;
  for (const auto& p : pages) listed += p.markers.size();
  EXPECT_EQ(listed, 36u);
  EXPECT_EQ(detected(pages, scene.dictionary).size(), 36u);
  // A3 holds more per page.
  EXPECT_LT(marker_sheets(scene, "scene.json", {.dpi = 100, .paper = paper_by_name("a3")}).size(), pages.size());
}

TEST(MarkerSheet, PagesRecordTheirDpi) {
  test::TempFolder dir("demoplan_marker_sheet");
  const auto pages = marker_sheets(scene_with(1, 0.03), "scene.json", {.dpi = 150});
  save_png_at_dpi(dir.file("page.png"), pages[0].image, 150);
  EXPECT_NEAR(png_dpi(dir.file("page.png")), 150, 0.02);  // PNG stores whole pixels per metre
  const cv::Mat back = cv::imread(dir.file("page.png"), cv::IMREAD_GRAYSCALE);
  ASSERT_EQ(back.size(), pages[0].image.size());
  EXPECT_EQ(cv::countNonZero(back != pages[0].image), 0);
  // A PNG written without a resolution says so; a file that is no PNG is refused.
  cv::imwrite(dir.file("plain.png"), pages[0].image);
  EXPECT_EQ(png_dpi(dir.file("plain.png")), 0.0);
  EXPECT_THROW(png_dpi(dir.write("not.png", "GIF89a")), InputError);
}

TEST(MarkerSheet, TooLargeOrNoMarkersIsRefusedNamingTheField) {
  MarkerScene scene = scene_with(1, 0.03);
  scene.objects[0].markers[2].size = 0.2;  // 267 mm with its white border: more than A4's 190 mm
  try {
    marker_sheets(scene, "cell_markers.json");
    FAIL() << "a 200 mm marker fit on A4";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "cell_markers.json");
    EXPECT_EQ(e.field(), "objects[0].markers[2].size");
    EXPECT_NE(std::string(e.what()).find("a4"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(marker_sheets(scene, "cell_markers.json", {.paper = paper_by_name("a3")}));
  scene.objects[0].markers.clear();
  try {
    marker_sheets(scene, "cell_markers.json");
    FAIL() << "an empty sheet was made";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "objects");
  }
  EXPECT_THROW(paper_by_name("b5"), InputError);
}
