#pragma once
// The one exception lib/map throws for a bad or unreadable map file.

#include <filesystem>
#include <stdexcept>
#include <string>

namespace playerkit::map {

class MapFileError : public std::runtime_error {
 public:
  // "file: message"
  MapFileError(const std::filesystem::path& file, const std::string& message);
  // "file:line:col: message" (1-based), for errors at a place in a YAML file.
  MapFileError(const std::filesystem::path& file, int line, int column, const std::string& message);

  // 0 when the error has no place in the file.
  int line() const { return line_; }
  int column() const { return column_; }

 private:
  int line_ = 0;
  int column_ = 0;
};

}  // namespace playerkit::map
