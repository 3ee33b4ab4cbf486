#pragma once
// Lines of Player 1.5's text log format (logfile-format.md), as writelog wrote
// them: two "##" header lines, then one line per data message and "sync" lines.
//
//   out << log::log_file_header();
//   out << log::format_data_line(message, "robot1", 6665);
//   out << log::format_sync_line(now_seconds, "robot1", 6665);
//
// Options (text_log_format.hpp) choose the file version (0.0.0 by default, or
// 1.6.5's 0.2.0) and the decimals of the prefix times: 6 by default (every
// microsecond; a compatible extension), 3 for byte-exact 1.5 output.
//
// Laser, position, position3d, gps, truth and fiducial get the fields of the
// chosen version; wifi, sonar, ir, power, bumper, localize, ptz and blobfinder
// get playerkit's extension fields (lib/log/README.md); every other interface
// gets the common prefix only, as in 1.5. So does a zero-length data message
// (readlog publishes one before its first line): there is nothing to write,
// and the reader gives it back as empty.

#include <cstdint>
#include <string>
#include <string_view>

#include "log/text_log_format.hpp"
#include "protocol/message.hpp"

namespace playerkit::log {

// "## Player version 1.5 \n## File version 0.0.0 \n", or for 0.2.0
// "## Player version 1.6.5 \n## File version 0.2.0 \n".
std::string log_file_header(const TextLogWriterOptions& options = {});

// One data line for a data message: server time (header time), host, port,
// interface, index, data time (header timestamp), then the interface's fields.
// Ends with '\n'. Throws protocol::DecodeError when the payload does not fit its
// struct, std::invalid_argument for a message that is not data, an interface
// code Player 1.5 does not name, or a host that is empty or holds whitespace
// (the format separates fields by spaces), or options it does not know.
std::string format_data_line(const protocol::Message& message, std::string_view host,
                             std::uint16_t port, const TextLogWriterOptions& options = {});

// A "sync" line at `time` (seconds): the common prefix with interface "sync",
// index 00 and the data time equal to `time`. Same host rules as above.
std::string format_sync_line(double time, std::string_view host, std::uint16_t port,
                             const TextLogWriterOptions& options = {});
// The same at an exact time (no rounding through a double at 6 decimals).
std::string format_sync_line(protocol::Timestamp time, std::string_view host, std::uint16_t port,
                             const TextLogWriterOptions& options = {});

}  // namespace playerkit::log
