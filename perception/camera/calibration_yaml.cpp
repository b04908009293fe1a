#include "perception/camera/calibration_yaml.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <map>
#include <optional>
#include <string_view>

#include "core/error.h"
#include "core/io/one_line.h"
#include "perception/camera/calibration_text.h"

namespace demoplan::perception {

namespace {

// A calibration file is a few kB; the calibration sample's image points for 100 views are
// ~200 kB. The cap bounds the reader's time and memory on whatever a user opens.

std::string line_at(int number) { return "line " + std::to_string(number); }

// Text from the file quoted in a message: one line, and short.
std::string quote(std::string_view s) {
  constexpr size_t kMax = 40;
  const std::string q = one_line(std::string(s.substr(0, kMax)));
  return "'" + q + (s.size() > kMax ? "...'" : "'");
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

struct Line {
  std::string_view text;  // without the line break
  int number = 0;         // 1-based
  int indent = 0;         // leading spaces
  bool blank = false;     // only spaces, or a comment
};

// One "key: value" of a block mapping. The lines indented under it ([block_begin, block_end)
// of the reader's lines) are parsed only for the keys that are read.
struct Entry {
  std::string key;
  std::string value;  // the scalar (unquoted), or a flow collection joined onto one line
  bool quoted = false;
  int line = 0;
  size_t block_begin = 0, block_end = 0;
};

class Reader {
public:
  Reader(std::string path, std::string text) : path_(std::move(path)), text_(std::move(text)) { split_lines(); }

  // The top-level mapping, after the header and up to the end of the document.
  std::map<std::string, Entry> document() {
    // The header comes first, as OpenCV 4.6 requires (it refuses a file without it).
    check_version(lines_[0].text);
    size_t i = 1;
    for (; i < lines_.size(); ++i) {
      const Line& l = lines_[i];
      if (l.blank) continue;
      const std::string_view c = trim(l.text);
      if (c[0] == '%') {
        // Other directives (%TAG) are ignored, as OpenCV does.
      } else if (l.indent == 0 && is_marker(c, "---")) {
        if (!trim(strip_comment(c.substr(3), l.number)).empty())
          throw InputError(path_, line_at(l.number), "expected nothing after '---'");
        ++i;
        break;
      } else {
        break;  // no "---": the mapping starts here
      }
    }
    size_t end = i;
    while (end < lines_.size()) {
      const Line& l = lines_[end];
      const std::string_view c = trim(l.text);
      if (!l.blank && l.indent == 0 && is_marker(c, "..."))
        break;  // the end of the document: what follows is not read
      if (!l.blank && l.indent == 0 && is_marker(c, "---"))
        throw InputError(path_, line_at(l.number), "a second YAML document ('---'); a calibration file holds one");
      ++end;
    }
    return mapping(i, end, "");
  }

  // The block mapping in lines [begin, end): entries at the indentation of its first line.
  // `owner` (the key it is under, empty at the top) names the field in errors.
  std::map<std::string, Entry> mapping(size_t begin, size_t end, const std::string& owner) {
    std::map<std::string, Entry> out;
    int indent = -1;
    size_t i = begin;
    while (i < end) {
      const Line& l = lines_[i];
      if (l.blank) {
        ++i;
        continue;
      }
      const std::string field = owner.empty() ? line_at(l.number) : owner;
      const std::string at = owner.empty() ? "" : line_at(l.number) + ": ";
      if (indent < 0) indent = l.indent;
      if (l.indent != indent)
        throw InputError(path_, field, at + "indented by " + std::to_string(l.indent) + " spaces where the mapping has " +
                                           std::to_string(indent));
      Entry e = entry(i, end, field, at);
      i = e.block_end;
      const std::string key = e.key;
      if (!out.emplace(key, std::move(e)).second)
        throw InputError(path_, owner.empty() ? one_line(key) : owner,
                         line_at(l.number) + ": key " + quote(key) + " appears twice");
    }
    return out;
  }

  const std::string& path() const { return path_; }

private:
  void split_lines() {
    size_t start = 0;
    int number = 1;
    while (start <= text_.size()) {
      size_t nl = text_.find('\n', start);
      if (nl == std::string::npos) nl = text_.size();
      std::string_view t(text_.data() + start, nl - start);
      if (!t.empty() && t.back() == '\r') t.remove_suffix(1);
      Line l{t, number, 0, false};
      while (static_cast<size_t>(l.indent) < t.size() && t[l.indent] == ' ') ++l.indent;
      const std::string_view c = trim(t);
      l.blank = c.empty() || c[0] == '#';
      if (!l.blank && t[l.indent] == '\t')
        throw InputError(path_, line_at(number), "a tab in the indentation (YAML indents with spaces)");
      lines_.push_back(l);
      start = nl + 1;
      ++number;
    }
  }

  static bool is_marker(std::string_view c, std::string_view marker) {
    return c.rfind(marker, 0) == 0 && (c.size() == marker.size() || c[marker.size()] == ' ' || c[marker.size()] == '\t');
  }

  // "%YAML:1.0", "%YAML 1.2" (OpenCV reads YAML 1.x), after a UTF-8 byte order mark if any.
  void check_version(std::string_view c) const {
    if (c.rfind("\xEF\xBB\xBF", 0) == 0) c.remove_prefix(3);
    bool ok = c.rfind("%YAML", 0) == 0;
    std::string_view v = ok ? trim(c.substr(5)) : c;
    if (ok && !v.empty() && v[0] == ':') v = trim(v.substr(1));
    else ok = ok && c.size() > 5 && (c[5] == ' ' || c[5] == '\t');
    if (const size_t hash = v.find(" #"); hash != std::string_view::npos) v = trim(v.substr(0, hash));
    ok = ok && v.size() > 2 && v.substr(0, 2) == "1." &&
         v.substr(2).find_first_not_of("0123456789") == std::string_view::npos;
    if (!ok)
      throw InputError(path_, line_at(1), "an OpenCV calibration file starts with the header '%YAML:1.0', not " + quote(c));
  }

  // A quote opens a quoted scalar only where a scalar starts (not in "o'clock").
  static bool opens_quote(std::string_view c, size_t k) {
    return (c[k] == '"' || c[k] == '\'') && (k == 0 || std::string_view(" \t[{,:").find(c[k - 1]) != std::string_view::npos);
  }

  // The line without its comment ('#' at its start or after a space, outside quotes). Quoted
  // scalars must close on their line.
  std::string_view strip_comment(std::string_view c, int number) const {
    char in_quote = 0;
    for (size_t k = 0; k < c.size(); ++k) {
      const char ch = c[k];
      if (in_quote == '"') {
        if (ch == '\\') ++k;
        else if (ch == '"') in_quote = 0;
      } else if (in_quote == '\'') {
        if (ch == '\'' && k + 1 < c.size() && c[k + 1] == '\'') ++k;
        else if (ch == '\'') in_quote = 0;
      } else if (ch == '#' && (k == 0 || c[k - 1] == ' ' || c[k - 1] == '\t')) {
        return c.substr(0, k);
      } else if (opens_quote(c, k)) {
        in_quote = ch;
      }
    }
    if (in_quote) throw InputError(path_, line_at(number), "a quoted string must end on its line");
    return c;
  }

  // The entry starting at line i; its flow continuation lines and the lines indented under it
  // end at e.block_end.
  Entry entry(size_t i, size_t end, const std::string& field, const std::string& at) const {
    const Line& l = lines_[i];
    Entry e;
    e.line = l.number;
    std::string_view c = trim(strip_comment(trim(l.text), l.number));
    if (c[0] == '-' && (c.size() == 1 || c[1] == ' '))
      throw InputError(path_, field, at + "expected 'key: value', found a sequence item (not read here)");
    // The key: quoted, or plain up to the first ": " (or ':' at the end of the line).
    size_t colon;
    if (c[0] == '"' || c[0] == '\'') {
      const size_t close = c.find(c[0], 1);
      if (close == std::string_view::npos) throw InputError(path_, field, at + "unterminated quoted key");
      e.key = std::string(c.substr(1, close - 1));
      colon = close + 1;
      if (colon >= c.size() || c[colon] != ':')
        throw InputError(path_, field, at + "expected ':' after the key " + quote(e.key));
    } else {
      colon = 0;
      while ((colon = c.find(':', colon)) != std::string_view::npos && colon + 1 < c.size() && c[colon + 1] != ' ' &&
             c[colon + 1] != '\t')
        ++colon;
      if (colon == std::string_view::npos) throw InputError(path_, field, at + "expected 'key: value', found " + quote(c));
      e.key = std::string(trim(c.substr(0, colon)));
      if (e.key.empty() || std::string_view("[]{}!&*|>?,").find(e.key[0]) != std::string_view::npos)
        throw InputError(path_, field, at + "expected 'key: value', found " + quote(c));
    }
    std::string_view v = trim(c.substr(colon + 1));
    if (!v.empty() && v[0] == '!') {  // a tag: "!!opencv-matrix"
      const size_t sp = v.find_first_of(" \t");
      v = sp == std::string_view::npos ? std::string_view() : trim(v.substr(sp));
    }
    size_t next = i + 1;
    if (!v.empty() && (v[0] == '[' || v[0] == '{')) {
      // Errors in it name the key (at the top) or the key it is under.
      next = flow(v, i, end, e, at.empty() ? one_line(e.key) : field, at.empty() ? "" : at + one_line(e.key) + ": ");
    } else if (!v.empty() && (v[0] == '"' || v[0] == '\'')) {
      e.value = unquote(v, l.number, field, at);
      e.quoted = true;
    } else {
      e.value = std::string(v);
    }
    // The lines indented further belong to this entry.
    e.block_begin = next;
    while (next < end && (lines_[next].blank || lines_[next].indent > l.indent)) ++next;
    while (next > e.block_begin && lines_[next - 1].blank) --next;  // blank lines after it are not its
    e.block_end = next;
    return e;
  }

  // A flow collection starting with v on line i, possibly continued on the next lines until its
  // brackets close; joined into e.value. Returns the line after it.
  size_t flow(std::string_view v, size_t i, size_t end, Entry& e, const std::string& field, const std::string& at) const {
    int depth = 0;
    size_t k = i;
    std::string_view part = v;
    for (;;) {
      char in_quote = 0;
      for (size_t j = 0; j < part.size(); ++j) {
        const char ch = part[j];
        if (in_quote) {
          if (in_quote == '"' && ch == '\\') ++j;
          else if (ch == in_quote) in_quote = 0;
        } else if (opens_quote(part, j)) {
          in_quote = ch;
        } else if (ch == '[' || ch == '{') {
          ++depth;
        } else if (ch == ']' || ch == '}') {
          if (--depth == 0) {
            if (!trim(part.substr(j + 1)).empty())
              throw InputError(path_, field, at + "text after the closing '" + std::string(1, ch) + "' on " +
                                                 line_at(lines_[k].number));
            e.value.append(part.substr(0, j + 1));
            return k + 1;
          }
        }
      }
      e.value.append(part);
      e.value += ' ';
      do {
        if (++k >= end)
          throw InputError(path_, field, at + "the '" + std::string(1, v[0]) + "' on " + line_at(e.line) + " is not closed");
      } while (lines_[k].blank);
      part = trim(strip_comment(trim(lines_[k].text), lines_[k].number));
    }
  }

  std::string unquote(std::string_view v, int number, const std::string& field, const std::string& at) const {
    const char q = v[0];
    std::string out;
    size_t k = 1;
    for (; k < v.size(); ++k) {
      if (q == '"' && v[k] == '\\' && k + 1 < v.size()) out += v[++k];
      else if (q == '\'' && v[k] == '\'' && k + 1 < v.size() && v[k + 1] == '\'') out += v[++k];
      else if (v[k] == q) break;
      else out += v[k];
    }
    if (k >= v.size() || !trim(v.substr(k + 1)).empty())
      throw InputError(path_, field, at + "text after the quoted string on " + line_at(number));
    return out;
  }

  std::string path_;
  std::string text_;
  std::vector<Line> lines_;
};

std::optional<int> parse_int(const Entry& e) {
  if (e.quoted) return std::nullopt;
  return parse_opencv_int(e.value);
}

// Reads the keys of an OpenCV calibration file from the reader's top-level mapping.
class Calibration {
public:
  explicit Calibration(Reader& r) : r_(r), top_(r.document()) {}

  const Entry* find(std::initializer_list<const char*> names) const {
    for (const char* n : names)
      if (auto it = top_.find(n); it != top_.end()) return &it->second;
    return nullptr;
  }

  int positive_int(const Entry& e) const {
    const std::optional<int> x = parse_int(e);
    if (!x || *x <= 0)
      throw InputError(r_.path(), e.key, line_at(e.line) + ": must be a positive integer, not " + quote(e.value) +
                                             (e.quoted ? " (quoted)" : ""));
    return *x;
  }

  // A mapping {rows, cols, dt, data} of at most max_elements numbers, row-major. Sizes are
  // checked before the data is looked at, and the data is split only as far as rows x cols.
  std::vector<double> matrix(const Entry& e, int max_elements, int* rows, int* cols) const {
    const std::string& path = r_.path();
    const std::string key = one_line(e.key);
    const std::string at = line_at(e.line) + ": ";
    if (!e.value.empty() || e.block_begin == e.block_end)
      throw InputError(path, key, at + "must be an !!opencv-matrix (rows, cols, dt, data) indented under the key");
    const std::map<std::string, Entry> m = r_.mapping(e.block_begin, e.block_end, key);
    auto get = [&](const char* name) -> const Entry& {
      const auto it = m.find(name);
      if (it == m.end()) throw InputError(path, key, at + std::string(name) + " is missing");
      if (it->second.block_begin != it->second.block_end)
        throw InputError(path, key, line_at(it->second.line) + ": " + name + " must be on one line");
      return it->second;
    };
    const Entry &re = get("rows"), &ce = get("cols"), &de = get("data");
    const std::optional<int> r = parse_int(re), c = parse_int(ce);
    if (!r || !c) throw InputError(path, key, line_at((r ? ce : re).line) + ": rows and cols must be integers");
    if (*r < 1 || *c < 1 || *r > max_elements || *c > max_elements || *r * *c > max_elements)
      throw InputError(path, key, at + "must have at most " + std::to_string(max_elements) + " elements (rows x cols)");
    const size_t n = static_cast<size_t>(*r * *c);
    const std::string_view d = de.value;
    const std::string data_at = line_at(de.line) + ": data";
    if (de.quoted || d.empty() || d.front() != '[' || d.back() != ']')
      throw InputError(path, key, data_at + " must be a sequence [ ... ] of rows x cols = " + std::to_string(n) + " numbers");
    std::vector<double> out;
    const std::string_view inner = trim(d.substr(1, d.size() - 2));
    size_t start = 0;
    while (!inner.empty() && start <= inner.size()) {
      if (out.size() == n)
        throw InputError(path, key, data_at + " holds more than rows x cols = " + std::to_string(n) + " numbers");
      size_t comma = inner.find(',', start);
      if (comma == std::string_view::npos) comma = inner.size();
      const std::string_view item = trim(inner.substr(start, comma - start));
      const std::string index = data_at + "[" + std::to_string(out.size()) + "]";
      const std::optional<double> x = parse_opencv_number(item);
      if (!x) throw InputError(path, key, index + " is not a number: " + quote(item));
      if (!std::isfinite(*x)) throw InputError(path, key, index + " is not a finite number");
      out.push_back(*x);
      start = comma + 1;
    }
    if (out.size() != n)
      throw InputError(path, key, data_at + " must hold rows x cols = " + std::to_string(n) + " numbers, not " +
                                      std::to_string(out.size()));
    *rows = *r;
    *cols = *c;
    return out;
  }

private:
  Reader& r_;
  std::map<std::string, Entry> top_;
};

}  // namespace

OpenCvCalibration read_calibration_yaml(const std::string& path) {
  Reader reader(path, read_calibration_text(path));
  const Calibration cal(reader);
  OpenCvCalibration out;
  const Entry* k = cal.find({"camera_matrix", "cameraMatrix", "K"});
  if (!k) throw InputError(path, "camera_matrix", "missing (also looked for cameraMatrix, K)");
  int rows = 0, cols = 0;
  const std::vector<double> km = cal.matrix(*k, 9, &rows, &cols);
  if (rows != 3 || cols != 3) throw InputError(path, one_line(k->key), line_at(k->line) + ": must be a 3x3 matrix");
  std::copy(km.begin(), km.end(), out.camera_matrix.begin());
  if (const Entry* d = cal.find({"distortion_coefficients", "dist_coeffs", "distCoeffs", "D"}))
    out.distortion = cal.matrix(*d, 14, &rows, &cols);
  const Entry *w = cal.find({"image_width"}), *h = cal.find({"image_height"});
  if (!w || !h) throw InputError(path, w ? "image_height" : "image_width", "missing image_width / image_height");
  out.image_width = cal.positive_int(*w);
  out.image_height = cal.positive_int(*h);
  return out;
}

}  // namespace demoplan::perception
