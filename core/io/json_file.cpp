#include "core/io/json_file.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "core/io/atomic_file.h"
#include "core/io/one_line.h"

namespace demoplan {

Json read_json_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "", "cannot open file");
  try {
    return Json::parse(in);
  } catch (const Json::exception& e) {
    // A syntax error (parse_error) or a number too large for a double (out_of_range 406,
    // "1e999": found by fuzzing, it used to escape as an uncaught exception).
    std::string what = e.what();
    // "[json.exception.parse_error.101] parse error at line 3, column 5: ..." -> keep the tail.
    if (auto pos = what.find("] "); what.rfind("[json.exception.", 0) == 0 && pos != std::string::npos)
      what = what.substr(pos + 2);
    throw InputError(path, "", "invalid JSON: " + what);
  }
}

void write_json_file_atomic(const std::string& path, const Json& value, int indent) {
  write_file_atomic(path, value.dump(indent) + '\n');
}

void JsonField::fail(const std::string& reason) const {
  throw InputError(file_, path_.empty() ? "(top level)" : one_line(path_), one_line(reason));
}

JsonField JsonField::operator[](const std::string& key) const {
  if (!value_->is_object()) fail("must be an object");
  auto it = value_->find(key);
  const std::string p = path_.empty() ? key : path_ + "." + key;
  if (it == value_->end()) throw InputError(file_, one_line(p), "missing");
  return JsonField(*it, file_, p);
}

JsonField JsonField::operator[](size_t index) const {
  if (!value_->is_array()) fail("must be an array");
  const std::string p = path_ + "[" + std::to_string(index) + "]";
  if (index >= value_->size())
    throw InputError(file_, one_line(p), "missing (array has " + std::to_string(value_->size()) + " entries)");
  return JsonField((*value_)[index], file_, p);
}

bool JsonField::has(const std::string& key) const {
  return value_->is_object() && value_->contains(key);
}

size_t JsonField::size() const {
  if (!value_->is_array()) fail("must be an array");
  return value_->size();
}

double JsonField::number() const {
  if (!value_->is_number()) fail("must be a number");
  const double v = value_->get<double>();
  if (!std::isfinite(v)) fail("must be a finite number");
  return v;
}

int JsonField::integer() const {
  if (!value_->is_number_integer()) fail("must be an integer");
  if (value_->is_number_unsigned()) {
    const auto v = value_->get<std::uint64_t>();
    if (v > static_cast<std::uint64_t>(std::numeric_limits<int>::max())) fail("is out of range");
    return static_cast<int>(v);
  }
  const auto v = value_->get<std::int64_t>();
  if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max()) fail("is out of range");
  return static_cast<int>(v);
}

bool JsonField::boolean() const {
  if (!value_->is_boolean()) fail("must be true or false");
  return value_->get<bool>();
}

std::string JsonField::string() const {
  if (!value_->is_string()) fail("must be a string");
  return value_->get<std::string>();
}

Eigen::VectorXd JsonField::vector() const {
  Eigen::VectorXd v(size());
  for (Eigen::Index i = 0; i < v.size(); ++i) v[i] = (*this)[static_cast<size_t>(i)].number();
  return v;
}

Json pose_matrix_json(const Pose& T) {
  Json rows = Json::array();
  for (int r = 0; r < 4; ++r) rows.push_back({T(r, 0), T(r, 1), T(r, 2), T(r, 3)});
  return rows;
}

Pose JsonField::pose(double rotation_tol) const {
  if (!value_->is_array() || value_->size() != 4) fail("must be a 4x4 matrix (4 rows of 4 numbers)");
  Eigen::Matrix4d M;
  for (int r = 0; r < 4; ++r) {
    const JsonField row = (*this)[r];
    if (!row.value().is_array() || row.size() != 4) row.fail("must be a row of 4 numbers");
    for (int c = 0; c < 4; ++c) {
      const JsonField cell = row[c];
      if (cell.value().is_null()) cell.fail("is null (NaN in the source data?)");
      M(r, c) = cell.number();
    }
  }
  if ((M.row(3) - Eigen::RowVector4d(0, 0, 0, 1)).cwiseAbs().maxCoeff() > 1e-9)
    fail("last row must be [0, 0, 0, 1]");
  if (!is_rotation(M.topLeftCorner<3, 3>(), rotation_tol))
    fail("rotation block is not orthonormal with determinant 1");
  Pose T = Pose::Identity();
  T.matrix() = M;
  return T;
}

void check_format(const JsonField& root, const std::string& format, int version, const std::string& kind) {
  if (!root.value().is_object()) root.fail("not a demoplan " + (kind.empty() ? format : kind) + " (expected a JSON object)");
  const JsonField f = root["format"];  // throws when missing
  if (!f.value().is_string() || f.value().get<std::string>() != format)
    f.fail((kind.empty() ? std::string() : "not a demoplan " + kind + ": ") + "expected '" + format + "'");
  const int v = root["version"].integer();
  if (v != version)
    root["version"].fail("unsupported " + (kind.empty() ? std::string() : kind + " ") + "version " + std::to_string(v) +
                         " (this demoplan reads version " + std::to_string(version) + ")");
}

}  // namespace demoplan
