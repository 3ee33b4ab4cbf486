#pragma once
// Tells a Player text log from a CARMEN log by its content (never its name),
// plain or gzip-compressed.
//
//   switch (log::detect_log_format(path)) {
//     case log::LogFormat::kPlayer: ...   // TextLogReader
//     case log::LogFormat::kCarmen: ...   // CarmenLogReader
//   }
//
// The first line that is not blank or a comment decides:
//   Player  "## Player version ..." / "## File version ..." header lines, or a
//           data line "<time> <host> <port> <interface> <index> <time> ...";
//   CARMEN  a line starting with an upper-case keyword (FLASER, ODOM, PARAM,
//           NEFF, VERTEX2, ...: unknown keywords count, as CARMEN's readers
//           skip them).
// A line that is neither, or a file with no deciding line among its first
// kMaxDetectionLines, is an error naming the file and the line.

#include <cstddef>
#include <filesystem>
#include <istream>
#include <optional>
#include <string_view>

namespace playerkit::log {

enum class LogFormat { kPlayer, kCarmen };

// "player" / "carmen".
std::string_view to_string(LogFormat format);

// What one line says about its file's format: nullopt for a blank or comment
// line (it says nothing). Throws std::runtime_error for a line that belongs
// to neither format.
std::optional<LogFormat> classify_log_line(std::string_view line);

inline constexpr std::size_t kMaxDetectionLines = 1000;

// Reads lines from `in` until one decides. `name` only goes into errors, as
// "name:line: message". Throws std::runtime_error when no line decides.
LogFormat detect_log_format(std::istream& in, std::string_view name);

// Opens the file (open_log_input: plain or gzip) and detects its format.
// Throws std::runtime_error for an unreadable file, damaged gzip data before
// the deciding line, or content that is neither format.
LogFormat detect_log_format(const std::filesystem::path& path);

}  // namespace playerkit::log
