#include "config/source_location.hpp"

namespace playerkit::config {

std::string to_string(const SourceLocation& where) {
  if (where.line <= 0) return where.file;
  return where.file + ":" + std::to_string(where.line) + ":" + std::to_string(where.column);
}

std::ostream& operator<<(std::ostream& out, const SourceLocation& where) {
  return out << to_string(where);
}

}  // namespace playerkit::config
