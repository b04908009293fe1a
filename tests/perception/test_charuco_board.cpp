// The ChArUco board: its file (round trip, clear errors) and the printable page (its size at a
// DPI, and the board on it where its geometry says, as OpenCV finds it).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <opencv2/aruco/charuco.hpp>
#include <opencv2/imgcodecs.hpp>

#include "core/error.h"
#include "perception/camera/charuco_board.h"
#include "perception/markers/marker_dictionary.h"
#include "perception/printing/printed_page.h"
#include "tests/support/temp_folder.h"

namespace fs = std::filesystem;
using namespace demoplan;
using namespace demoplan::perception;

namespace {

class CharucoBoardFile : public ::testing::Test {
protected:
  std::string file(const std::string& text) { return dir_.write("board.json", text); }
  // The error loading `text` gives: its field, and its message.
  std::pair<std::string, std::string> error_of(const std::string& text) {
    try {
      load_charuco_board(file(text));
    } catch (const InputError& e) {
      return {e.field(), e.what()};
    }
    return {"", "no error"};
  }
  test::TempFolder dir_{"demoplan_charuco_board"};
};

std::string board_json(const std::string& squares_y, const std::string& extra = "") {
  return R"({"format": "demoplan-charuco-board", "version": 1, "squares_x": 7, "squares_y": )" + squares_y +
         R"(, "square_length": 0.03, "marker_length": 0.022, "dictionary": "DICT_5X5_100")" + extra + "}";
}

}  // namespace

TEST_F(CharucoBoardFile, RoundTrip) {
  CharucoBoard b;
  b.squares_x = 9;
  b.squares_y = 7;
  b.square_length = 0.025;
  b.marker_length = 0.019;
  b.dictionary = "DICT_4X4_100";
  b.first_id = 20;
  const std::string p = dir_.file("b.json");
  save_charuco_board(p, b);
  const CharucoBoard c = load_charuco_board(p);
  EXPECT_EQ(c.squares_x, 9);
  EXPECT_EQ(c.squares_y, 7);
  EXPECT_DOUBLE_EQ(c.square_length, 0.025);
  EXPECT_DOUBLE_EQ(c.marker_length, 0.019);
  EXPECT_EQ(c.dictionary, "DICT_4X4_100");
  EXPECT_EQ(c.first_id, 20);
  // The OpenCV board takes the ids from first_id on.
  const auto board = c.make();
  ASSERT_EQ(board->ids.size(), 31u);
  EXPECT_EQ(board->ids.front(), 20);
  EXPECT_EQ(board->ids.back(), 50);
}

TEST_F(CharucoBoardFile, FirstIdIsOptional) { EXPECT_EQ(load_charuco_board(file(board_json("5"))).first_id, 0); }

TEST_F(CharucoBoardFile, EvenRowsAreRejected) {
  const auto [field, what] = error_of(board_json("4"));
  EXPECT_EQ(field, "squares_y");
  EXPECT_NE(what.find("odd"), std::string::npos) << what;
  EXPECT_NE(what.find("OpenCV 4.6"), std::string::npos) << what;
  EXPECT_EQ(what.rfind(dir_.file("board.json"), 0), 0u) << what;
}

TEST_F(CharucoBoardFile, MissingAndBadFieldsAreNamed) {
  EXPECT_EQ(error_of(R"({"format": "demoplan-charuco-board", "version": 1, "squares_x": 7, "squares_y": 5,
                         "square_length": 0.03, "dictionary": "DICT_5X5_100"})")
                .first,
            "marker_length");
  EXPECT_EQ(error_of(R"({"format": "demoplan-charuco-board", "version": 1, "squares_x": 7, "squares_y": 5,
                         "square_length": 0.03, "marker_length": 0.03, "dictionary": "DICT_5X5_100"})")
                .first,
            "marker_length");
  EXPECT_EQ(error_of(board_json("5").replace(board_json("5").find("DICT_5X5_100"), 12, "DICT_9X9_1")).first, "dictionary");
  EXPECT_EQ(error_of(board_json("5", R"(, "first_id": 95)")).first, "first_id");  // 17 markers beyond id 99
  EXPECT_EQ(error_of(board_json("\"five\"")).first, "squares_y");
  EXPECT_EQ(error_of(R"({"format": "demoplan-camera", "version": 1})").first, "format");
  EXPECT_EQ(error_of(board_json("5").replace(board_json("5").find("\"version\": 1"), 12, "\"version\": 2")).first,
            "version");
}

TEST(CharucoPrintable, SizeAtDpi) {
  const CharucoBoard b;  // 7 x 5 squares of 30 mm
  for (double dpi : {300.0, 150.0}) {
    const PrintableBoard p = printable_board(b, dpi);
    const double px_per_mm = dpi / 25.4;
    EXPECT_EQ(p.image.cols, std::lround(210 * px_per_mm) + 2 * std::lround(kPrintMarginMm * px_per_mm)) << dpi;
    EXPECT_EQ(p.image.rows, std::lround(150 * px_per_mm) + std::lround(kPrintFooterMm * px_per_mm) +
                                2 * std::lround(kPrintMarginMm * px_per_mm))
        << dpi;
    EXPECT_NEAR(p.px_per_m_x, px_per_mm * 1000, 0.5 / 0.21) << dpi;
  }
}

// OpenCV finds every marker and corner of the page, each corner where px_per_m and offset put it.
TEST(CharucoPrintable, CornersWhereTheGeometrySays) {
  CharucoBoard b;
  b.first_id = 30;
  const PrintableBoard p = printable_board(b, 120);
  const auto board = b.make();
  std::vector<std::vector<cv::Point2f>> marker_corners;
  std::vector<int> ids;
  cv::aruco::detectMarkers(p.image, marker_dictionary(b.dictionary), marker_corners, ids);
  EXPECT_EQ(int(ids.size()), b.marker_count());
  std::vector<cv::Point2f> corners;
  std::vector<int> corner_ids;
  cv::aruco::interpolateCornersCharuco(marker_corners, ids, p.image, board, corners, corner_ids);
  ASSERT_EQ(int(corner_ids.size()), b.corner_count());
  for (size_t k = 0; k < corners.size(); ++k) {
    const cv::Point3f q = board->chessboardCorners[size_t(corner_ids[k])];
    EXPECT_NEAR(corners[k].x, p.px_per_m_x * q.x + p.offset.x, 1.0) << corner_ids[k];
    EXPECT_NEAR(corners[k].y, p.px_per_m_y * q.y + p.offset.y, 1.0) << corner_ids[k];
  }
}

// The written page is the drawn one, and records its resolution so it prints at true scale.
TEST(CharucoPrintable, SavedPageRecordsItsDpi) {
  test::TempFolder dir("demoplan_charuco_page");
  const CharucoBoard b;
  save_printable_board(dir.file("board.png"), b, 200);
  EXPECT_NEAR(png_dpi(dir.file("board.png")), 200, 0.02);  // PNG stores whole pixels per metre
  const cv::Mat back = cv::imread(dir.file("board.png"), cv::IMREAD_GRAYSCALE);
  const cv::Mat drawn = printable_board(b, 200).image;
  ASSERT_EQ(back.size(), drawn.size());
  EXPECT_EQ(cv::countNonZero(back != drawn), 0);
  for (const auto& entry : fs::directory_iterator(fs::path(dir.file("board.png")).parent_path()))
    EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path();  // no temporary left
}
