#pragma once
// Pages meant to be printed at true scale (the calibration board, part markers): the PNG records
// its resolution (a pHYs chunk), so print dialogs size it right, and a 50 mm scale bar lets the
// user check the print with a ruler.
#include <string>

#include <opencv2/core.hpp>

namespace demoplan::perception {

// Text on printed pages: OpenCV's Hershey simplex at `scale`, strokes `thickness` pixels wide.
struct PageFont {
  double scale = 1.0;
  int thickness = 1;
};
// The font whose capitals are `cap_mm` high at `px_per_mm`.
PageFont page_font(double px_per_mm, double cap_mm = 3.5);
void put_page_text(cv::Mat& page, const std::string& text, cv::Point baseline_left, const PageFont& font);
// Width and height in pixels of `text` in `font`.
cv::Size page_text_size(const std::string& text, const PageFont& font);

// A 50 mm bar with a tick every 10 mm and the label "50 mm", its top-left corner at `top_left`.
// Returns the height it takes.
int draw_scale_bar(cv::Mat& page, cv::Point top_left, double px_per_mm, const PageFont& font);

// Writes `image` (8-bit) as PNG recording `dpi`, atomically. Throws InputError naming `path`.
void save_png_at_dpi(const std::string& path, const cv::Mat& image, double dpi);
// The resolution a PNG file records (pHYs in pixels per metre), in dots per inch; 0 when the file
// records none. Throws InputError when it is not a PNG.
double png_dpi(const std::string& path);

}  // namespace demoplan::perception
