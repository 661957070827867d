#pragma once
// Where bad input was found: "imu.csv:17:23: field 'gz': not a number 'abc'".
#include <cstddef>
#include <string>

namespace sinu::dataset {

struct Diagnostic {
  std::string file;         // path as given by the user
  std::size_t line = 0;     // 1-based; 0 = the file as a whole
  std::size_t column = 0;   // 1-based character column; 0 = the line as a whole
  std::string message;

  /// "file:line:column: message" (line/column omitted when 0).
  std::string to_string() const;
};

}  // namespace sinu::dataset
