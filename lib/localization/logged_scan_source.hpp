#pragma once
// The per-format halves of LoggedScanReader (internal to lib/localization).

#include <cstddef>
#include <filesystem>
#include <memory>
#include <optional>

#include "localization/logged_scan.hpp"
#include "localization/logged_scan_reader.hpp"
#include "log/log_clock.hpp"

namespace playerkit::localization {

class LoggedScanSource {
 public:
  virtual ~LoggedScanSource() = default;
  virtual std::optional<LoggedScan> next() = 0;
  virtual std::size_t malformed_lines() const = 0;
};

// `clock` (never null) gives the scans' times (log/log_clock_reader.hpp).
std::unique_ptr<LoggedScanSource> make_player_scan_source(const std::filesystem::path& log,
                                                          const LoggedScanReaderOptions& options,
                                                          std::shared_ptr<const log::LogClock> clock);
std::unique_ptr<LoggedScanSource> make_carmen_scan_source(const std::filesystem::path& log,
                                                          const LoggedScanReaderOptions& options,
                                                          std::shared_ptr<const log::LogClock> clock);

}  // namespace playerkit::localization
