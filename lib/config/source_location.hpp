#pragma once
// Where something was written in a config file. Every token, property and
// section carries one so that errors and warnings can point at the exact spot.

#include <ostream>
#include <string>

namespace playerkit::config {

struct SourceLocation {
  std::string file;  // the path as given to the loader, or as resolved for an include
  int line = 0;      // 1-based; 0 when the problem concerns the whole file
  int column = 0;    // 1-based, counted in bytes (a tab is one column)

  friend bool operator==(const SourceLocation&, const SourceLocation&) = default;
};

// "file:line:col", or just "file" when the line is unknown (e.g. a file that
// cannot be opened).
std::string to_string(const SourceLocation& where);
std::ostream& operator<<(std::ostream& out, const SourceLocation& where);

}  // namespace playerkit::config
