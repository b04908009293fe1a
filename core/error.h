#pragma once
// Bad input is reported with one exception type that names where the problem is.
#include <stdexcept>
#include <string>

namespace demoplan {

// Thrown by every loader for malformed or missing input. what() is one line:
// "<file>: <field>: <reason>" (field omitted when the problem is the whole file).
class InputError : public std::runtime_error {
public:
  InputError(const std::string& file, const std::string& field, const std::string& reason)
      : std::runtime_error(compose(file, field, reason)), file_(file), field_(field), reason_(reason) {}

  const std::string& file() const { return file_; }
  const std::string& field() const { return field_; }
  const std::string& reason() const { return reason_; }

private:
  static std::string compose(const std::string& file, const std::string& field,
                             const std::string& reason) {
    std::string s = file;
    if (!field.empty()) s += ": " + field;
    return s + ": " + reason;
  }
  std::string file_;
  std::string field_;
  std::string reason_;
};

}  // namespace demoplan
