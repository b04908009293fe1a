#include "perception/camera/charuco_board.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.h"
#include "core/io/json_file.h"
#include "perception/markers/marker_dictionary.h"
#include "perception/printing/printed_page.h"

namespace demoplan::perception {

namespace {

constexpr const char* kFormat = "demoplan-charuco-board";
constexpr int kVersion = 1;

std::string mm(double metres) {
  std::ostringstream s;
  s << std::round(metres * 1e4) / 10;  // to 0.1 mm
  return s.str();
}

}  // namespace

cv::Ptr<cv::aruco::CharucoBoard> CharucoBoard::make() const {
  auto board = cv::aruco::CharucoBoard::create(squares_x, squares_y, static_cast<float>(square_length),
                                               static_cast<float>(marker_length), marker_dictionary(dictionary));
  if (first_id != 0) {
    std::vector<int> ids = board->ids;
    for (int& id : ids) id += first_id;
    board->setIds(ids);
  }
  return board;
}

void validate(const CharucoBoard& b, const std::function<void(const std::string&, const std::string&)>& fail) {
  if (b.squares_x < 2 || b.squares_x > 100) fail("squares_x", "must be 2..100");
  if (b.squares_y < 3 || b.squares_y > 100) fail("squares_y", "must be 3..100");
  if (b.squares_y % 2 == 0)
    fail("squares_y", "must be odd (is " + std::to_string(b.squares_y) +
                          "): OpenCV 4.6 changed the ChArUco pattern of boards with an even number of rows");
  if (!(b.square_length > 0) || !(b.square_length < 10)) fail("square_length", "must be > 0 and < 10 m");
  if (!(b.marker_length > 0) || !(b.marker_length < b.square_length))
    fail("marker_length", "must be > 0 and smaller than square_length");
  if (!is_marker_dictionary(b.dictionary)) fail("dictionary", "unknown ArUco dictionary '" + b.dictionary + "'");
  if (b.first_id < 0) fail("first_id", "must be >= 0");
  const long long last = static_cast<long long>(b.first_id) + b.marker_count() - 1;
  const int size = marker_dictionary(b.dictionary)->bytesList.rows;
  if (last >= size)
    fail("first_id", "the board's " + std::to_string(b.marker_count()) + " markers need ids up to " + std::to_string(last) +
                         "; " + b.dictionary + " has ids 0.." + std::to_string(size - 1));
}

CharucoBoard load_charuco_board(const std::string& path) {
  if (!std::filesystem::is_regular_file(path)) throw InputError(path, "", "board file not found");
  const Json json = read_json_file(path);
  const JsonField root(json, path);
  check_format(root, kFormat, kVersion, "ChArUco board");
  CharucoBoard b;
  b.squares_x = root["squares_x"].integer();
  b.squares_y = root["squares_y"].integer();
  b.square_length = root["square_length"].number();
  b.marker_length = root["marker_length"].number();
  b.dictionary = root["dictionary"].string();
  if (root.has("first_id")) b.first_id = root["first_id"].integer();
  validate(b, [&](const std::string& field, const std::string& reason) { throw InputError(path, field, reason); });
  return b;
}

void save_charuco_board(const std::string& path, const CharucoBoard& b) {
  write_json_file_atomic(path, Json{{"format", kFormat},
                                    {"version", kVersion},
                                    {"units", "metres"},
                                    {"squares_x", b.squares_x},
                                    {"squares_y", b.squares_y},
                                    {"square_length", b.square_length},
                                    {"marker_length", b.marker_length},
                                    {"dictionary", b.dictionary},
                                    {"first_id", b.first_id}});
}

PrintableBoard printable_board(const CharucoBoard& b, double dpi) {
  PrintableBoard p;
  p.dpi = dpi;
  const double px_per_mm = dpi / 25.4;
  const int margin = static_cast<int>(std::lround(kPrintMarginMm * px_per_mm));
  const int board_w = static_cast<int>(std::lround(b.width() * 1000 * px_per_mm));
  const int board_h = static_cast<int>(std::lround(b.height() * 1000 * px_per_mm));
  const int footer = static_cast<int>(std::lround(kPrintFooterMm * px_per_mm));
  p.image = cv::Mat(board_h + footer + 2 * margin, board_w + 2 * margin, CV_8UC1, cv::Scalar(255));
  p.px_per_m_x = board_w / b.width();
  p.px_per_m_y = board_h / b.height();
  // Pixel k covers [k, k + 1) of the page: the board's edge x = 0 is at pixel coordinate margin - 0.5.
  p.offset = {margin - 0.5, margin - 0.5};
  // Our own drawing rather than CharucoBoard::draw, which fits the board into the image with
  // rounding of its own: here every edge is where px_per_m and offset say.
  auto px = [&](double x, double y) { return cv::Point(int(std::lround(margin + x * p.px_per_m_x)), int(std::lround(margin + y * p.px_per_m_y))); };
  const auto board = b.make();
  // A square is white when it holds a marker (OpenCV's pattern, whatever the row count).
  std::vector<char> white(size_t(b.squares_x) * b.squares_y, 0);
  for (const auto& corners : board->objPoints) {
    const cv::Point3f c = (corners[0] + corners[2]) * 0.5f;
    white[size_t(int(c.y / b.square_length)) * b.squares_x + int(c.x / b.square_length)] = 1;
  }
  for (int y = 0; y < b.squares_y; ++y)
    for (int x = 0; x < b.squares_x; ++x)
      if (!white[size_t(y) * b.squares_x + x])
        cv::rectangle(p.image, cv::Rect(px(x * b.square_length, y * b.square_length), px((x + 1) * b.square_length, (y + 1) * b.square_length)),
                      cv::Scalar(0), cv::FILLED);
  const auto dictionary = marker_dictionary(b.dictionary);
  for (size_t k = 0; k < board->objPoints.size(); ++k) {
    const cv::Point tl = px(board->objPoints[k][0].x, board->objPoints[k][0].y);
    const cv::Point br = px(board->objPoints[k][2].x, board->objPoints[k][2].y);
    cv::Mat marker;
    cv::aruco::drawMarker(dictionary, board->ids[k], std::min(br.x - tl.x, br.y - tl.y), marker, 1);
    marker.copyTo(p.image(cv::Rect(tl, marker.size())));
  }

  // Caption: two lines of text, then the scale bar; the text shrinks to fit a narrow board.
  const std::string line1 = "ChArUco " + std::to_string(b.squares_x) + " x " + std::to_string(b.squares_y) +
                            " squares, square " + mm(b.square_length) + " mm, marker " + mm(b.marker_length) + " mm, " +
                            b.dictionary + ", ids " + std::to_string(b.first_id) + "-" +
                            std::to_string(b.first_id + b.marker_count() - 1);
  const std::string line2 = "print at 100 %, check the scale bar: 50 mm";
  PageFont font = page_font(px_per_mm);
  const int width = page_text_size(line1, font).width;
  if (width > board_w + margin) font = page_font(px_per_mm, 3.5 * (board_w + margin) / width);
  const int top = margin + board_h;
  put_page_text(p.image, line1, {margin, top + int(7 * px_per_mm)}, font);
  put_page_text(p.image, line2, {margin, top + int(13 * px_per_mm)}, font);
  draw_scale_bar(p.image, {margin, top + int(15 * px_per_mm)}, px_per_mm, font);
  return p;
}

void save_printable_board(const std::string& png_path, const CharucoBoard& board, double dpi) {
  save_png_at_dpi(png_path, printable_board(board, dpi).image, dpi);
}

}  // namespace demoplan::perception
