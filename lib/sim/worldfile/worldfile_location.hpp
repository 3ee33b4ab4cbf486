#pragma once
// Where something was written in a world file. Tokens, properties, values and
// entities all carry one, so that errors and warnings point at the exact spot
// even inside an included file or a macro body.

#include <string>

namespace playerkit::sim::worldfile {

struct SourceLocation {
  std::string file;  // as given to the reader, or as resolved for an include
  int line = 0;      // 1-based; 0 when the problem concerns the whole file
  int column = 0;    // 1-based, in bytes (a tab is one column)

  friend bool operator==(const SourceLocation&, const SourceLocation&) = default;
};

// "file:line:col", or just "file" when the line is unknown.
std::string to_string(const SourceLocation& where);

}  // namespace playerkit::sim::worldfile
