#pragma once
// A ChArUco board (a chessboard whose white squares hold ArUco markers) for calibrating a
// camera's intrinsics: its description, its file and a printable image at true scale.
// (The ArUco grid board that gives the camera's pose in the cell is MarkerBoard, marker_board.h.)
//
// File "demoplan-charuco-board" version 1 (JSON), lengths in metres:
//   {"format": "demoplan-charuco-board", "version": 1,
//    "squares_x": 7, "squares_y": 5,          // squares along the printed rows, and rows
//    "square_length": 0.030, "marker_length": 0.022,
//    "dictionary": "DICT_5X5_100",
//    "first_id": 0}                           // optional: the markers' ids start here
// squares_y must be odd: OpenCV 4.6 changed where the markers sit on boards with an even number
// of rows, so such a board printed with another OpenCV version would be misread.
// Board frame (OpenCV 4.6's CharucoBoard): origin at the board's top-left outer corner as
// printed, x to the right along the rows, y down the page, z into the board.
#include <functional>
#include <string>

#include <opencv2/aruco/charuco.hpp>
#include <opencv2/core.hpp>

namespace demoplan::perception {

struct CharucoBoard {
  int squares_x = 7, squares_y = 5;
  double square_length = 0.030;  // m
  double marker_length = 0.022;  // m, black square of a marker
  std::string dictionary = "DICT_5X5_100";
  int first_id = 0;

  int marker_count() const { return squares_x * squares_y / 2; }
  int corner_count() const { return (squares_x - 1) * (squares_y - 1); }  // inner chessboard corners
  double width() const { return squares_x * square_length; }
  double height() const { return squares_y * square_length; }
  // Call validate() first: OpenCV asserts on nonsense.
  cv::Ptr<cv::aruco::CharucoBoard> make() const;
};

// Calls `fail(field, reason)` for the first problem found (field: the file's field name); `fail`
// must throw. Checks sizes, odd rows, marker inside its square, dictionary and its ids.
void validate(const CharucoBoard& board, const std::function<void(const std::string& field, const std::string& reason)>& fail);

// Throws InputError naming the file and the field.
CharucoBoard load_charuco_board(const std::string& path);
// Writes "demoplan-charuco-board" version 1, atomically.
void save_charuco_board(const std::string& path, const CharucoBoard& board);

// The page to print: the board at `dpi`, a white margin of kPrintMarginMm all round, and below
// the board a caption (squares, sizes in mm, dictionary, "print at 100 %") and a 50 mm scale bar.
inline constexpr double kPrintMarginMm = 15.0;
inline constexpr double kPrintFooterMm = 28.0;  // caption and scale bar, between board and bottom margin
struct PrintableBoard {
  cv::Mat image;  // 8-bit grey
  double dpi = 300;
  // Board coordinates (metres, board frame) to pixel coordinates of `image` (pixel centres at
  // integers): u = px_per_m_x * x + offset.x, v = px_per_m_y * y + offset.y.
  double px_per_m_x = 0, px_per_m_y = 0;
  cv::Point2d offset;
};
PrintableBoard printable_board(const CharucoBoard& board, double dpi = 300);
// Writes printable_board() as PNG (throws InputError when it cannot be written).
void save_printable_board(const std::string& png_path, const CharucoBoard& board, double dpi = 300);

}  // namespace demoplan::perception
