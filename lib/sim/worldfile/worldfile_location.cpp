#include "sim/worldfile/worldfile_location.hpp"

namespace playerkit::sim::worldfile {

std::string to_string(const SourceLocation& where) {
  if (where.line <= 0) return where.file;
  return where.file + ":" + std::to_string(where.line) + ":" + std::to_string(where.column);
}

}  // namespace playerkit::sim::worldfile
