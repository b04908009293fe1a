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
  const int font = cv::FONT_HERSHEY_SIMPLEX;
  const std::string line1 = "ChArUco " + std::to_string(b.squares_x) + " x " + std::to_string(b.squares_y) +
                            " squares, square " + mm(b.square_length) + " mm, marker " + mm(b.marker_length) + " mm, " +
                            b.dictionary + ", ids " + std::to_string(b.first_id) + "-" +
                            std::to_string(b.first_id + b.marker_count() - 1);
  const std::string line2 = "print at 100 %, check the scale bar: 50 mm";
  int base = 0;
  const cv::Size unit = cv::getTextSize(line1, font, 1.0, 1, &base);
  double scale = 3.5 * px_per_mm / unit.height;  // 3.5 mm capitals
  scale = std::min(scale, (board_w + margin) / double(unit.width));
  const int thickness = std::max(1, int(std::lround(scale * 1.5)));
  const int top = margin + board_h;
  cv::putText(p.image, line1, {margin, top + int(7 * px_per_mm)}, font, scale, cv::Scalar(0), thickness, cv::LINE_AA);
  cv::putText(p.image, line2, {margin, top + int(13 * px_per_mm)}, font, scale, cv::Scalar(0), thickness, cv::LINE_AA);
  // 50 mm bar, with a tick every 10 mm.
  const int bar_y = top + int(17 * px_per_mm), bar_h = std::max(2, int(std::lround(2 * px_per_mm)));
  const int bar_len = int(std::lround(50 * px_per_mm));
  cv::rectangle(p.image, cv::Rect(margin, bar_y, bar_len, bar_h), cv::Scalar(0), cv::FILLED);
  for (int t = 0; t <= 5; ++t) {
    const int x = margin + int(std::lround(t * 10 * px_per_mm));
    cv::rectangle(p.image, cv::Rect(std::min(x, margin + bar_len - thickness), bar_y - bar_h, thickness, bar_h), cv::Scalar(0), cv::FILLED);
  }
  cv::putText(p.image, "50 mm", {margin + bar_len + int(3 * px_per_mm), bar_y + bar_h}, font, scale, cv::Scalar(0),
              thickness, cv::LINE_AA);
  return p;
}

void save_printable_board(const std::string& png_path, const CharucoBoard& board, double dpi) {
  const PrintableBoard p = printable_board(board, dpi);
  // Atomic as every file we write: beside it under a temporary name (still .png: imwrite picks
  // the encoder by extension), then renamed.
  const std::string tmp = png_path + ".part.png";
  bool ok = false;
  std::error_code ec;
  try {
    ok = cv::imwrite(tmp, p.image);
  } catch (const cv::Exception& e) {
    std::filesystem::remove(tmp, ec);
    throw InputError(png_path, "", std::string("cannot write the image: ") + e.err);
  }
  if (ok) std::filesystem::rename(tmp, png_path, ec);
  if (!ok || ec) {
    std::filesystem::remove(tmp, ec);
    throw InputError(png_path, "", "cannot write the image");
  }
}

}  // namespace demoplan::perception
