#include "localization/logged_scan_reader.hpp"

#include "localization/logged_scan_source.hpp"
#include "log/log_clock_reader.hpp"

namespace playerkit::localization {

LoggedScanReader::LoggedScanReader(const std::filesystem::path& log, LoggedScanReaderOptions options)
    : format_(log::detect_log_format(log)),
      clock_(log::audit_log_times(log)),
      source_(format_ == log::LogFormat::kPlayer ? make_player_scan_source(log, options, clock_)
                                                 : make_carmen_scan_source(log, options, clock_)) {}

LoggedScanReader::~LoggedScanReader() = default;
LoggedScanReader::LoggedScanReader(LoggedScanReader&&) noexcept = default;
LoggedScanReader& LoggedScanReader::operator=(LoggedScanReader&&) noexcept = default;

std::optional<LoggedScan> LoggedScanReader::next() {
  auto scan = source_->next();
  if (scan) {
    if (!scan->odometry) ++scans_without_odometry_;
    if (!scan->truth) ++scans_without_truth_;
  }
  return scan;
}

std::size_t LoggedScanReader::malformed_lines() const { return source_->malformed_lines(); }

}  // namespace playerkit::localization
