#include "perception/printing/printed_page.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.h"
#include "core/io/atomic_file.h"

namespace demoplan::perception {

namespace {

constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;
constexpr double kMetresPerInch = 0.0254;

// PNG's CRC-32 (ISO 3309, the polynomial of zlib).
std::uint32_t crc32(const unsigned char* data, size_t size) {
  static const std::array<std::uint32_t, 256> table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t n = 0; n < 256; ++n) {
      std::uint32_t c = n;
      for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[n] = c;
    }
    return t;
  }();
  std::uint32_t c = 0xFFFFFFFFu;
  for (size_t i = 0; i < size; ++i) c = table[(c ^ data[i]) & 0xFF] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

void put_u32(std::vector<unsigned char>& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<unsigned char>(v >> shift));
}

std::uint32_t get_u32(const unsigned char* p) {
  return std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 | std::uint32_t(p[3]);
}

constexpr unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
constexpr size_t kIhdrEnd = 8 + 4 + 4 + 13 + 4;  // signature, then IHDR: length, type, data, CRC

}  // namespace

PageFont page_font(double px_per_mm, double cap_mm) {
  int base = 0;
  const cv::Size unit = cv::getTextSize("H", kFont, 1.0, 1, &base);
  PageFont f;
  f.scale = cap_mm * px_per_mm / unit.height;
  f.thickness = std::max(1, static_cast<int>(std::lround(f.scale * 1.5)));
  return f;
}

void put_page_text(cv::Mat& page, const std::string& text, cv::Point baseline_left, const PageFont& font) {
  cv::putText(page, text, baseline_left, kFont, font.scale, cv::Scalar(0), font.thickness, cv::LINE_AA);
}

cv::Size page_text_size(const std::string& text, const PageFont& font) {
  int base = 0;
  return cv::getTextSize(text, kFont, font.scale, font.thickness, &base);
}

int draw_scale_bar(cv::Mat& page, cv::Point top_left, double px_per_mm, const PageFont& font) {
  const int bar_h = std::max(2, static_cast<int>(std::lround(2 * px_per_mm)));
  const int bar_len = static_cast<int>(std::lround(50 * px_per_mm));
  const int tick = font.thickness;
  const int bar_y = top_left.y + bar_h;  // the ticks rise one bar height above the bar
  cv::rectangle(page, cv::Rect(top_left.x, bar_y, bar_len, bar_h), cv::Scalar(0), cv::FILLED);
  for (int t = 0; t <= 5; ++t) {
    const int x = top_left.x + static_cast<int>(std::lround(t * 10 * px_per_mm));
    cv::rectangle(page, cv::Rect(std::min(x, top_left.x + bar_len - tick), bar_y - bar_h, tick, bar_h), cv::Scalar(0),
                  cv::FILLED);
  }
  put_page_text(page, "50 mm", {top_left.x + bar_len + static_cast<int>(3 * px_per_mm), bar_y + bar_h}, font);
  return 2 * bar_h;
}

void save_png_at_dpi(const std::string& path, const cv::Mat& image, double dpi) {
  std::vector<unsigned char> png;
  try {
    if (!cv::imencode(".png", image, png)) throw InputError(path, "", "cannot encode the image as PNG");
  } catch (const cv::Exception& e) {
    throw InputError(path, "", std::string("cannot encode the image as PNG: ") + e.err);
  }
  if (png.size() < kIhdrEnd || !std::equal(std::begin(kSignature), std::end(kSignature), png.begin()))
    throw InputError(path, "", "the PNG encoder wrote no PNG");
  // pHYs: pixels per metre in x and y, unit 1 (metre); it must come before the image data, so
  // right after IHDR.
  const auto ppm = static_cast<std::uint32_t>(std::lround(dpi / kMetresPerInch));
  std::vector<unsigned char> chunk;
  put_u32(chunk, 9);
  const size_t typed = chunk.size();
  for (char c : {'p', 'H', 'Y', 's'}) chunk.push_back(static_cast<unsigned char>(c));
  put_u32(chunk, ppm);
  put_u32(chunk, ppm);
  chunk.push_back(1);
  put_u32(chunk, crc32(chunk.data() + typed, chunk.size() - typed));
  png.insert(png.begin() + kIhdrEnd, chunk.begin(), chunk.end());
  write_file_atomic(path, std::string_view(reinterpret_cast<const char*>(png.data()), png.size()));
}

double png_dpi(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "cannot open the file");
  const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() < 8 || !std::equal(std::begin(kSignature), std::end(kSignature), bytes.begin()))
    throw InputError(path, "", "not a PNG file");
  for (size_t at = 8; at + 12 <= bytes.size();) {
    const std::uint32_t length = get_u32(&bytes[at]);
    const std::string type(bytes.begin() + at + 4, bytes.begin() + at + 8);
    if (at + 12 + length > bytes.size()) break;
    if (type == "pHYs" && length == 9 && bytes[at + 16] == 1) return get_u32(&bytes[at + 8]) * kMetresPerInch;
    if (type == "IDAT" || type == "IEND") break;  // pHYs comes before the image data
    at += 12 + length;
  }
  return 0;
}

}  // namespace demoplan::perception
