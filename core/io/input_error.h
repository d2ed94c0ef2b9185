#pragma once
// The error every file reader throws: one line naming the file, the line (when known), the field and
// the problem, e.g. "test1.json:14: sensors.gps.position_variance_m2: must be positive, got -5".
// Whatever the parts hold, what() is one line (io/error_line.h): input quoted in a message should go
// through io::quoted(), and the composed line is made safe again here.
#include <stdexcept>
#include <string>

#include "io/error_line.h"

namespace reckoner::io {

class InputError : public std::runtime_error {
 public:
  InputError(std::string file, int line, std::string field, const std::string& message)
      : std::runtime_error(compose(file, line, field, message)),
        file_(std::move(file)),
        line_(line),
        field_(std::move(field)) {}

  [[nodiscard]] const std::string& file() const { return file_; }
  [[nodiscard]] int line() const { return line_; }  ///< 0 when not applicable
  [[nodiscard]] const std::string& field() const { return field_; }

 private:
  static std::string compose(const std::string& file, int line, const std::string& field,
                             const std::string& msg) {
    std::string s = oneLine(file, kMaxQuotedChars);
    if (line > 0) s.append(1, ':').append(std::to_string(line));
    s.append(": ");
    if (!field.empty()) s.append(oneLine(field, kMaxQuotedChars)).append(": ");
    s.append(oneLine(msg));
    return s;
  }
  std::string file_;
  int line_;
  std::string field_;
};

}  // namespace reckoner::io
