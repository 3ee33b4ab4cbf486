#pragma once
// playerkit's extension interfaces of the text log (internal): wifi, sonar, ir,
// power, bumper, localize, ptz and blobfinder, in the style of 1.5's fields
// (metres, radians, one line per message). Layouts: lib/log/README.md. The
// same layout is used in files of version 0.0.0 and 0.2.0.

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "log/text_log_fields.hpp"

namespace playerkit::log {

// True when `interface` is one of the extension interfaces.
bool is_extension_interface(std::uint16_t interface);

// Appends the fields of an extension interface's payload (decoded from its
// wire struct). Throws protocol::DecodeError when the payload does not fit,
// std::invalid_argument when the format cannot hold a value (a wifi ip with
// whitespace, a blobfinder channel pointing past its blobs).
void append_extension_fields(std::string& line, std::uint16_t interface,
                             std::span<const std::uint8_t> payload);

// The wire payload from the fields after the prefix. Throws LogParseError.
std::vector<std::uint8_t> extension_payload(std::uint16_t interface, const LineFields& fields);

}  // namespace playerkit::log
