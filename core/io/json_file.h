#pragma once
// Reading JSON with errors that name the file and the field ("objects_poses[0][12]").
#include <nlohmann/json.hpp>
#include <string>

#include "core/geometry/se3.h"

namespace demoplan {

using Json = nlohmann::json;

// Parses a file; throws InputError with the line and column of a syntax error.
Json read_json_file(const std::string& path);

// Writes atomically: to a temporary file beside `path`, then renamed over it.
void write_json_file_atomic(const std::string& path, const Json& value, int indent = 1);

// A JSON value with its file and path, so every accessor can report where it failed.
class JsonField {
public:
  JsonField(const Json& value, std::string file, std::string path = "")
      : value_(&value), file_(std::move(file)), path_(std::move(path)) {}

  const Json& value() const { return *value_; }
  const std::string& path() const { return path_; }
  const std::string& file() const { return file_; }

  JsonField operator[](const std::string& key) const;  // throws when missing
  JsonField operator[](size_t index) const;            // throws when out of range
  bool has(const std::string& key) const;
  size_t size() const;  // of an array; throws if not an array

  double number() const;  // finite number
  int integer() const;
  bool boolean() const;
  std::string string() const;
  bool is_null() const { return value_->is_null(); }
  // A 4x4 row-major homogeneous transform with a rotation block within `tol` of orthonormal.
  Pose pose(double rotation_tol = 1e-5) const;
  Eigen::VectorXd vector() const;

  [[noreturn]] void fail(const std::string& reason) const;

private:
  const Json* value_;
  std::string file_;
  std::string path_;
};

// A pose as the 4x4 row-major matrix JsonField::pose() reads.
Json pose_matrix_json(const Pose& T);

// Checks the "format" and "version" fields every demoplan file starts with; throws InputError.
// `kind` (e.g. "project") names the file's kind when its format is another's.
void check_format(const JsonField& root, const std::string& format, int version, const std::string& kind = "");

}  // namespace demoplan
