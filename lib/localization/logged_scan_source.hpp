#pragma once
// The per-format halves of LoggedScanReader (internal to lib/localization).

#include <cstddef>
#include <filesystem>
#include <memory>
#include <optional>

#include "localization/logged_scan.hpp"
#include "localization/logged_scan_reader.hpp"

namespace playerkit::localization {

class LoggedScanSource {
 public:
  virtual ~LoggedScanSource() = default;
  virtual std::optional<LoggedScan> next() = 0;
  virtual std::size_t malformed_lines() const = 0;
};

std::unique_ptr<LoggedScanSource> make_player_scan_source(const std::filesystem::path& log,
                                                          const LoggedScanReaderOptions& options);
std::unique_ptr<LoggedScanSource> make_carmen_scan_source(const std::filesystem::path& log,
                                                          const LoggedScanReaderOptions& options);

}  // namespace playerkit::localization
