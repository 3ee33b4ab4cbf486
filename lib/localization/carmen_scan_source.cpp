// CARMEN logs as LoggedScans (see logged_scan_reader.hpp for the choices).

#include <charconv>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>

#include "localization/logged_scan_source.hpp"
#include "log/carmen_log_reader.hpp"
#include "log/log_input.hpp"

namespace playerkit::localization {
namespace {

// carmen_to_player's numbering of CARMEN's lasers.
int laser_index_of(log::CarmenLaserKind kind) {
  using K = log::CarmenLaserKind;
  switch (kind) {
    case K::kFlaser:
    case K::kRawLaser1:
    case K::kRobotLaser1: return 0;
    case K::kRlaser:
    case K::kRawLaser2:
    case K::kRobotLaser2: return 1;
    case K::kLaser3:
    case K::kRawLaser3: return 2;
    case K::kLaser4:
    case K::kRawLaser4: return 3;
  }
  return -1;
}

geometry::Pose2 to_pose(const log::CarmenPose& pose) {
  return {pose.x, pose.y, geometry::normalize_angle(pose.theta)};
}

std::optional<double> positive_number(const std::string& text) {
  double value = 0;
  const auto parsed = std::from_chars(text.data(), text.data() + text.size(), value);
  if (parsed.ec != std::errc{} || parsed.ptr != text.data() + text.size() || !(value > 0)) return std::nullopt;
  return value;
}

class CarmenScanSource final : public LoggedScanSource {
 public:
  CarmenScanSource(const std::filesystem::path& log, const LoggedScanReaderOptions& options,
                   std::shared_ptr<const log::LogClock> clock)
      : options_(options),
        in_(log::open_log_input(log)),
        reader_(*in_, log.string(), {.strict = options.strict, .clock = std::move(clock)}),
        name_(log.string()) {}

  std::optional<LoggedScan> next() override {
    while (auto record = reader_.next()) {
      if (const auto* param = std::get_if<log::CarmenParam>(&*record)) {
        take_param(*param);
      } else if (const auto* odometry = std::get_if<log::CarmenOdometry>(&*record)) {
        latest_odometry_ = to_pose(odometry->pose);
      } else if (const auto* laser = std::get_if<log::CarmenLaser>(&*record)) {
        if (laser_index_of(laser->kind) == options_.laser_index) return scan_of(*laser);
      }
    }
    if (const auto error = in_->error()) throw std::runtime_error(name_ + ": " + *error);
    return std::nullopt;
  }

  std::size_t malformed_lines() const override { return reader_.malformed_lines(); }

 private:
  void take_param(const log::CarmenParam& param) {
    const char* wanted = options_.laser_index == 0   ? "robot_front_laser_max"
                         : options_.laser_index == 1 ? "robot_rear_laser_max"
                                                     : nullptr;
    if (wanted != nullptr && param.name == wanted) {
      if (const auto value = positive_number(param.value)) param_max_range_ = *value;
    }
  }

  LoggedScan scan_of(const log::CarmenLaser& laser) const {
    LoggedScan scan;
    scan.time = laser.stamp.ipc_timestamp;
    scan.ranges = laser.ranges;
    scan.angle_min = laser.config.start_angle;
    scan.angle_increment = laser.config.angular_resolution;
    scan.max_range = param_max_range_ ? *param_max_range_
                     : laser.config.maximum_range > 0 ? laser.config.maximum_range
                                                       : options_.default_max_range;
    if (laser.robot_pose) {
      scan.odometry = to_pose(*laser.robot_pose);
    } else {
      scan.odometry = latest_odometry_;
    }
    if (laser.laser_pose) scan.truth = to_pose(*laser.laser_pose);
    return scan;
  }

  LoggedScanReaderOptions options_;
  std::unique_ptr<log::LogInput> in_;
  log::CarmenLogReader reader_;
  std::string name_;
  std::optional<double> param_max_range_;
  std::optional<geometry::Pose2> latest_odometry_;
};

}  // namespace

std::unique_ptr<LoggedScanSource> make_carmen_scan_source(const std::filesystem::path& log,
                                                          const LoggedScanReaderOptions& options,
                                                          std::shared_ptr<const log::LogClock> clock) {
  return std::make_unique<CarmenScanSource>(log, options, std::move(clock));
}

}  // namespace playerkit::localization
