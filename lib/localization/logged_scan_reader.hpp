#pragma once
// Laser scans with their odometry and true poses, streamed from a Player text
// log (0.0.0 or 0.2.0) or a CARMEN log, plain or gzip; the format is told by
// content (log/log_format_detection.hpp). Constant memory: one scan at a time.
//
//   localization::LoggedScanReader reader("intel-corrected.log.gz");
//   while (auto scan = reader.next()) use(scan->ranges, *scan->odometry, scan->truth);
//
// Where the poses come from (README.md has the reasons):
//   Player  odometry: the position:0 pose with the scan's data time that
//           follows the laser line (as carmen_to_player writes it), else the
//           latest position:0 before the scan; truth: truth:<laser_index>
//           likewise. Poses are read from the text (mm, 0.001 rad), not
//           through the wire struct (whole degrees).
//   CARMEN  laser_index 0 = FLASER / ROBOTLASER1 / RAWLASER1, 1 = RLASER /
//           ROBOTLASER2 / RAWLASER2, 2 and 3 = LASER3/4, RAWLASER3/4 (as
//           carmen_to_player numbers them). odometry: the record's odom pose,
//           else the latest ODOM before it; truth: the record's laser pose
//           (x y theta): true for SLAM-corrected logs such as Radish's.
//           time: ipc_timestamp.
// Times: a log whose times are unusable is read by its LogClock
// (log/log_clock.hpp; a warning on stderr says so): the replaced scans get
// interpolated times, or file order on a synthetic clock.
// Max range: CARMEN PARAM robot_front_laser_max / robot_rear_laser_max when
// the log has it, else the record's laser config (FLASER: CARMEN's guess, 80
// m, below the 81.83 m no-return readings); Player: the option.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>

#include "localization/logged_scan.hpp"
#include "log/log_clock.hpp"
#include "log/log_format_detection.hpp"

namespace playerkit::localization {

struct LoggedScanReaderOptions {
  std::uint16_t laser_index = 0;
  // true: a malformed line throws log::LogParseError; false: skipped, counted.
  bool strict = false;
  // For logs that do not say (Player logs): CARMEN's SICK LMS maximum.
  double default_max_range = 80.0;
  // Player logs: called with every truth:<laser_index> sample at its own time
  // (on the log's clock), paired with a scan or not. A simulator's truth
  // device publishes every step; a recording may keep a scan and miss the
  // truth of its moment, and the scan then carries an older one.
  std::function<void(double time, const geometry::Pose2& pose)> on_truth{};
};

class LoggedScanSource;  // one per format, internal

class LoggedScanReader {
 public:
  // Throws std::runtime_error when the file cannot be read or is neither format.
  explicit LoggedScanReader(const std::filesystem::path& log, LoggedScanReaderOptions options = {});
  ~LoggedScanReader();
  LoggedScanReader(LoggedScanReader&&) noexcept;
  LoggedScanReader& operator=(LoggedScanReader&&) noexcept;

  // The next scan of the chosen laser, or nullopt at the end. Throws
  // std::runtime_error for damaged gzip data.
  std::optional<LoggedScan> next();

  log::LogFormat format() const { return format_; }
  // How the log's times were judged (synthetic(): scan times are file order).
  const log::LogClock& clock() const { return *clock_; }
  std::size_t malformed_lines() const;
  std::size_t scans_without_odometry() const { return scans_without_odometry_; }
  std::size_t scans_without_truth() const { return scans_without_truth_; }

 private:
  log::LogFormat format_;
  std::shared_ptr<const log::LogClock> clock_;
  std::unique_ptr<LoggedScanSource> source_;
  std::size_t scans_without_odometry_ = 0;
  std::size_t scans_without_truth_ = 0;
};

}  // namespace playerkit::localization
