#include "perception/camera/calibration_xml.h"

#include <tinyxml.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <optional>
#include <string_view>
#include <vector>

#include "core/error.h"
#include "core/io/one_line.h"
#include "core/model/xml_text.h"
#include "perception/camera/calibration_text.h"

namespace demoplan::perception {

namespace {


std::string line_of(const TiXmlElement& e) { return "line " + std::to_string(e.Row()); }

std::string quote(std::string_view s) {
  constexpr size_t kMax = 40;
  return "'" + one_line(std::string(s.substr(0, kMax))) + (s.size() > kMax ? "...'" : "'");
}

std::string_view trim(std::string_view s) {
  const size_t b = s.find_first_not_of(" \t\r\n");
  if (b == std::string_view::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

std::string_view text_of(const TiXmlElement& e) {
  const char* t = e.GetText();
  return t ? trim(t) : std::string_view();
}

class XmlCalibration {
public:
  XmlCalibration(std::string path, const TiXmlElement& root) : path_(std::move(path)), root_(root) {}

  const TiXmlElement* find(std::initializer_list<const char*> names) const {
    for (const char* n : names)
      if (const TiXmlElement* e = root_.FirstChildElement(n)) return e;
    return nullptr;
  }

  int positive_int(const TiXmlElement& e) const {
    const std::optional<int> x = parse_opencv_int(text_of(e));
    if (!x || *x <= 0)
      throw InputError(path_, one_line(e.Value()), line_of(e) + ": must be a positive integer, not " + quote(text_of(e)));
    return *x;
  }

  // <rows>, <cols>, <data> of at most max_elements numbers, row-major; the size is checked
  // before the data is split, and the data is split only as far as rows x cols.
  std::vector<double> matrix(const TiXmlElement& e, int max_elements, int* rows, int* cols) const {
    const std::string key = one_line(e.Value());
    const std::string at = line_of(e) + ": ";
    const TiXmlElement *re = e.FirstChildElement("rows"), *ce = e.FirstChildElement("cols"),
                       *de = e.FirstChildElement("data");
    if (!re || !ce || !de) throw InputError(path_, key, at + "must be an opencv-matrix (rows, cols, dt, data)");
    const std::optional<int> r = parse_opencv_int(text_of(*re)), c = parse_opencv_int(text_of(*ce));
    if (!r || !c) throw InputError(path_, key, at + "rows and cols must be integers");
    if (*r < 1 || *c < 1 || *r > max_elements || *c > max_elements || *r * *c > max_elements)
      throw InputError(path_, key, at + "must have at most " + std::to_string(max_elements) + " elements (rows x cols)");
    const size_t n = static_cast<size_t>(*r * *c);
    std::vector<double> out;
    const std::string_view d = text_of(*de);
    const std::string data_at = line_of(*de) + ": data";
    size_t k = 0;
    while ((k = d.find_first_not_of(" \t\r\n", k)) != std::string_view::npos) {
      if (out.size() == n)
        throw InputError(path_, key, data_at + " holds more than rows x cols = " + std::to_string(n) + " numbers");
      const size_t stop = std::min(d.find_first_of(" \t\r\n", k), d.size());
      const std::string_view item = d.substr(k, stop - k);
      const std::string index = data_at + "[" + std::to_string(out.size()) + "]";
      const std::optional<double> x = parse_opencv_number(item);
      if (!x) throw InputError(path_, key, index + " is not a number: " + quote(item));
      if (!std::isfinite(*x)) throw InputError(path_, key, index + " is not a finite number");
      out.push_back(*x);
      k = stop;
    }
    if (out.size() != n)
      throw InputError(path_, key, data_at + " must hold rows x cols = " + std::to_string(n) + " numbers, not " +
                                       std::to_string(out.size()));
    *rows = *r;
    *cols = *c;
    return out;
  }

private:
  std::string path_;
  const TiXmlElement& root_;
};

}  // namespace

OpenCvCalibration read_calibration_xml(const std::string& path) {
  TiXmlDocument doc;
  const std::string text = padded_for_tinyxml(read_calibration_text(path));
  doc.Parse(text.c_str());
  if (doc.Error())
    throw InputError(path, doc.ErrorRow() > 0 ? "line " + std::to_string(doc.ErrorRow()) : "",
                     one_line(std::string("XML error: ") + doc.ErrorDesc()));
  const TiXmlElement* root = doc.RootElement();
  if (!root || std::string_view(root->Value()) != "opencv_storage")
    throw InputError(path, "", "the root element must be <opencv_storage> (an OpenCV calibration file)");
  const XmlCalibration cal(path, *root);
  OpenCvCalibration out;
  const TiXmlElement* k = cal.find({"camera_matrix", "cameraMatrix", "K"});
  if (!k) throw InputError(path, "camera_matrix", "missing (also looked for cameraMatrix, K)");
  int rows = 0, cols = 0;
  const std::vector<double> km = cal.matrix(*k, 9, &rows, &cols);
  if (rows != 3 || cols != 3) throw InputError(path, one_line(k->Value()), line_of(*k) + ": must be a 3x3 matrix");
  std::copy(km.begin(), km.end(), out.camera_matrix.begin());
  if (const TiXmlElement* d = cal.find({"distortion_coefficients", "dist_coeffs", "distCoeffs", "D"}))
    out.distortion = cal.matrix(*d, 14, &rows, &cols);
  const TiXmlElement *w = cal.find({"image_width"}), *h = cal.find({"image_height"});
  if (!w || !h) throw InputError(path, w ? "image_height" : "image_width", "missing image_width / image_height");
  out.image_width = cal.positive_int(*w);
  out.image_height = cal.positive_int(*h);
  return out;
}

}  // namespace demoplan::perception
