#pragma once
// The two versions of the Player text log format and the writer's options.
//
//   0.0.0  Player 1.5's writelog (logfile-format.md §1-§3)
//   0.2.0  Player 1.6.5's writelog, as far as spec §6 describes it
//
// Both versions carry playerkit's extension interfaces (wifi with link
// fields, sonar, ir, power, bumper, localize, ptz, blobfinder) in the layout
// documented in lib/log/README.md.

#include <optional>
#include <string_view>

namespace playerkit::log {

enum class LogFormatVersion { k0_0_0, k0_2_0 };

// "0.0.0" / "0.2.0".
std::string_view to_string(LogFormatVersion version);
// nullopt for a version this library does not read.
std::optional<LogFormatVersion> parse_format_version(std::string_view text);

struct TextLogWriterOptions {
  // 0.0.0 by default: Player 1.5's readlog reads it.
  LogFormatVersion version = LogFormatVersion::k0_0_0;
  // Decimals of the prefix times (tokens 0 and 5): 6 keeps every microsecond
  // (1.5's readlog reads them with atof, so this is a compatible extension); 3
  // gives byte-exact 1.5 output. Only 3 and 6 are accepted.
  int time_decimals = 6;
};

}  // namespace playerkit::log
