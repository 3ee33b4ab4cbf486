#pragma once
// Lines of Player 1.5's text log format (logfile-format.md), as writelog wrote
// them: two "##" header lines, then one line per data message and "sync" lines.
//
//   out << log::log_file_header();
//   out << log::format_data_line(message, "robot1", 6665);
//
// Interfaces without data fields in 1.5 (everything but laser, position,
// position3d, gps, truth and fiducial) get the common prefix only, as in 1.5.

#include <cstdint>
#include <string>
#include <string_view>

#include "protocol/message.hpp"

namespace playerkit::log {

// "## Player version 1.5 \n## File version 0.0.0 \n"
std::string log_file_header();

// One data line for a data message: server time (header time), host, port,
// interface, index, data time (header timestamp), then the interface's fields.
// Ends with '\n'. Throws protocol::DecodeError when the payload does not fit.
std::string format_data_line(const protocol::Message& message, std::string_view host,
                             std::uint16_t port);

// A "sync" line at `time` (seconds).
std::string format_sync_line(double time, std::string_view host, std::uint16_t port);

}  // namespace playerkit::log
