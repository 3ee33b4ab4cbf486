#include "map/map_file_error.hpp"

#include "text/printable.hpp"

namespace playerkit::map {

MapFileError::MapFileError(const std::filesystem::path& file, const std::string& message)
    : std::runtime_error(text::printable(file.string() + ": " + message)) {}

MapFileError::MapFileError(const std::filesystem::path& file, int line, int column,
                           const std::string& message)
    : std::runtime_error(text::printable(file.string() + ":" + std::to_string(line) + ":" +
                                         std::to_string(column) + ": " + message)),
      line_(line),
      column_(column) {}

}  // namespace playerkit::map
