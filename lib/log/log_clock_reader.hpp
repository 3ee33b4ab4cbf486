#pragma once
// The LogClock of a log file (log_clock.hpp): its timed records' times read
// once, audited, and a warning on stderr the first time a process finds a
// file's times unusable.
//
//   const auto clock = log::audit_log_times(path);   // warns once if unusable
//   log::CarmenLogReader reader(*in, path.string(), {.clock = clock});
//
// The times audited are each format's file clock, the one a log is written in
// order of: Player, token 0 of every sync and data line; CARMEN, the
// logger_timestamp of every record but PARAM (configuration, stamped when the
// logger started or not at all). A reader given the clock replaces a record's
// unusable time in all its time fields (Player: token 0 and the data time;
// CARMEN: ipc and logger timestamps); usable records keep theirs.

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "log/log_clock.hpp"

namespace playerkit::log {

// The file-clock times of the log's timed records, in file order (a lenient
// read: malformed lines are not records). Throws std::runtime_error for an
// unreadable file or damaged gzip data.
std::vector<double> read_log_times(const std::filesystem::path& path);

// LogClock::audit(read_log_times(path)); when it replaces anything, the
// warning handler gets "PATH: <clock.describe()>" unless this process already
// reported the same for the same path.
std::shared_ptr<const LogClock> audit_log_times(const std::filesystem::path& path);

// Where the warnings go (default: a line on std::cerr). Returns the previous one.
using LogClockWarningHandler = std::function<void(const std::string& warning)>;
LogClockWarningHandler set_log_clock_warning_handler(LogClockWarningHandler handler);

}  // namespace playerkit::log
