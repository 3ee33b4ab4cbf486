// Player text logs as LoggedScans (see logged_scan_reader.hpp for the choices).

#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>

#include "log/text_log_tokens.hpp"
#include "localization/logged_scan_source.hpp"
#include "log/log_input.hpp"
#include "log/log_line.hpp"
#include "log/log_parse_error.hpp"
#include "log/text_log_reader.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/laser.hpp"

namespace playerkit::localization {
namespace {

// Player's laser angles are hundredths of a degree.
constexpr double kRadiansPerLaserAngleUnit = std::numbers::pi / 18000.0;

// x y yaw of a position or truth line, from the text: the wire structs hold
// whole degrees, the text 0.001 rad.
geometry::Pose2 pose_from_text(const std::string& line, bool truth_0_2_0) {
  const auto pose = log::read_text_pose(log::split_line_tokens(line), truth_0_2_0);
  return {pose.x, pose.y, geometry::normalize_angle(pose.yaw)};
}

LoggedScan scan_from_laser(const protocol::Message& message, double time, double max_range) {
  const auto data = protocol::decode<protocol::LaserData>(message.payload);
  LoggedScan scan;
  scan.time = time;
  scan.angle_min = data.min_angle * kRadiansPerLaserAngleUnit;
  scan.angle_increment = data.resolution * kRadiansPerLaserAngleUnit;
  scan.max_range = max_range;
  const double metres_per_unit = (data.range_res == 0 ? 1.0 : data.range_res) * 0.001;
  scan.ranges.reserve(data.range_count);
  for (std::size_t i = 0; i < data.range_count; ++i) scan.ranges.push_back(data.ranges[i] * metres_per_unit);
  return scan;
}

class PlayerScanSource final : public LoggedScanSource {
 public:
  PlayerScanSource(const std::filesystem::path& log, const LoggedScanReaderOptions& options,
                   std::shared_ptr<const log::LogClock> clock)
      : options_(options), clock_(std::move(clock)), in_(log::open_log_input(log)), name_(log.string()) {}

  std::optional<LoggedScan> next() override {
    std::string line;
    bool too_long = false;
    while (log::read_log_line(*in_, line, too_long)) {
      ++line_number_;
      if (too_long) {  // a malformed line (text::kMaxLineBytes)
        if (options_.strict) throw log::too_long_line_error(name_, line_number_);
        ++malformed_lines_;
        continue;
      }
      auto ready = take_line(line);
      if (ready) return ready;
    }
    if (const auto error = in_->error()) throw std::runtime_error(name_ + ": " + *error);
    return finish_pending();
  }

  std::size_t malformed_lines() const override { return malformed_lines_; }

 private:
  struct PendingScan {
    LoggedScan scan;
    protocol::Timestamp data_time;
    bool odometry_at_scan_time = false;
    bool truth_at_scan_time = false;
  };

  std::optional<LoggedScan> take_line(const std::string& line) {
    log::LogLine parsed;
    try {
      parsed = log::parse_log_line(line, name_, line_number_, version_);
      if (std::holds_alternative<log::SyncLine>(parsed)) {
        ++timed_lines_;
      } else if (const auto* data = std::get_if<log::DataLine>(&parsed)) {
        const std::size_t ordinal = timed_lines_++;
        if (data->device) return take_data(*data, line, ordinal);
      } else if (const auto* header = std::get_if<log::HeaderLine>(&parsed)) {
        take_header(*header);
      }
    } catch (const log::LogParseError&) {
      if (options_.strict || is_version_error_) throw;
      ++malformed_lines_;
    } catch (const std::exception& error) {  // a payload that does not decode, a bad pose field
      if (options_.strict) throw log::LogParseError(name_, line_number_, 1, error.what());
      ++malformed_lines_;
    }
    return std::nullopt;
  }

  void take_header(const log::HeaderLine& header) {
    if (header.name != "File version") return;
    const auto version = log::parse_format_version(header.value);
    if (!version) {
      is_version_error_ = true;  // every later line would be misread: not skippable
      throw log::LogParseError(name_, line_number_, header.value_column,
                               "file version " + header.value + " is not read here (0.0.0 and 0.2.0 are)");
    }
    version_ = *version;
  }

  // `ordinal` counts sync and data lines, as the log's clock does.
  std::optional<LoggedScan> take_data(const log::DataLine& data, const std::string& line, std::size_t ordinal) {
    const auto interface = data.device->interface;
    const auto index = data.device->index;
    if (interface == protocol::kLaserCode && index == options_.laser_index) {
      if (data.message.payload.empty()) return std::nullopt;  // readlog's placeholder
      auto finished = finish_pending();
      // Poses pair by the logged data times; the scan's own time comes from the log's clock.
      const double time = clock_->time_of(ordinal, data.data_time.seconds());
      PendingScan next{scan_from_laser(data.message, time, options_.default_max_range), data.data_time};
      next.scan.odometry = latest_odometry_;
      next.scan.truth = latest_truth_;
      pending_ = std::move(next);
      return finished;
    }
    const bool is_odometry = interface == protocol::kPositionCode && index == 0;
    const bool is_truth = interface == protocol::kTruthCode && index == options_.laser_index;
    if (!is_odometry && !is_truth) return std::nullopt;
    const auto pose = pose_from_text(line, is_truth && version_ == log::LogFormatVersion::k0_2_0);
    const bool at_scan_time = pending_ && pending_->data_time == data.data_time;
    if (is_odometry) {
      latest_odometry_ = pose;
      if (at_scan_time && !pending_->odometry_at_scan_time) {
        pending_->scan.odometry = pose;
        pending_->odometry_at_scan_time = true;
      }
    } else {
      latest_truth_ = pose;
      if (options_.on_truth) options_.on_truth(clock_->time_of(ordinal, data.data_time.seconds()), pose);
      if (at_scan_time && !pending_->truth_at_scan_time) {
        pending_->scan.truth = pose;
        pending_->truth_at_scan_time = true;
      }
    }
    if (pending_ && pending_->odometry_at_scan_time && pending_->truth_at_scan_time) return finish_pending();
    return std::nullopt;
  }

  std::optional<LoggedScan> finish_pending() {
    if (!pending_) return std::nullopt;
    LoggedScan scan = std::move(pending_->scan);
    pending_.reset();
    return scan;
  }

  LoggedScanReaderOptions options_;
  std::shared_ptr<const log::LogClock> clock_;
  std::unique_ptr<log::LogInput> in_;
  std::string name_;
  int line_number_ = 0;
  std::size_t timed_lines_ = 0;
  std::size_t malformed_lines_ = 0;
  bool is_version_error_ = false;
  log::LogFormatVersion version_ = log::LogFormatVersion::k0_0_0;
  std::optional<PendingScan> pending_;
  std::optional<geometry::Pose2> latest_odometry_;
  std::optional<geometry::Pose2> latest_truth_;
};

}  // namespace

std::unique_ptr<LoggedScanSource> make_player_scan_source(const std::filesystem::path& log,
                                                          const LoggedScanReaderOptions& options,
                                                          std::shared_ptr<const log::LogClock> clock) {
  return std::make_unique<PlayerScanSource>(log, options, std::move(clock));
}

}  // namespace playerkit::localization
