#include "log/text_log_writer.hpp"

#include <stdexcept>

namespace playerkit::log {

// Placeholder: the writer is being written (issue 4, player-cat --format log).
std::string log_file_header() { return "## Player version 1.5 \n## File version 0.0.0 \n"; }

std::string format_data_line(const protocol::Message&, std::string_view, std::uint16_t) {
  throw std::logic_error("format_data_line: not written yet");
}

std::string format_sync_line(double, std::string_view, std::uint16_t) {
  throw std::logic_error("format_sync_line: not written yet");
}

}  // namespace playerkit::log
