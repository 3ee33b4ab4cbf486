#include "log/log_conversion.hpp"
#include "log/text_log_units.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <type_traits>

#include "protocol/binary_codec.hpp"
#include "protocol/constants.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/laser.hpp"
#include "protocol/messages/position.hpp"
#include "protocol/messages/truth.hpp"

namespace playerkit::log {
namespace {

using namespace text_log_units;

using protocol::DeviceAddress;
using protocol::Message;
using protocol::Timestamp;


template <typename Int>
Int rounded(double value, const char* what) {
  const double r = std::round(value);
  if (!std::isfinite(r) || r < static_cast<double>(std::numeric_limits<Int>::min()) ||
      r > static_cast<double>(std::numeric_limits<Int>::max())) {
    throw std::invalid_argument(std::string(what) + " " + std::to_string(value) +
                                " does not fit the Player message");
  }
  return static_cast<Int>(r);
}

Timestamp to_timestamp(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0 || seconds >= 4294967296.0) {
    throw std::invalid_argument("time " + std::to_string(seconds) + " s is outside what Player times hold");
  }
  return Timestamp::from_seconds(seconds);
}

template <typename Struct>
Message data_message(DeviceAddress device, Timestamp server_time, Timestamp data_time, const Struct& value) {
  Message message;
  message.payload = protocol::encode(value);
  message.header = protocol::make_header(protocol::MessageType::kData, device, server_time, data_time);
  message.header.size = static_cast<std::uint32_t>(message.payload.size());
  return message;
}

protocol::PositionData position_of(const CarmenPose& pose, double tv, double rv) {
  protocol::PositionData data;
  data.xpos = rounded<std::int32_t>(pose.x * 1000.0, "x");
  data.ypos = rounded<std::int32_t>(pose.y * 1000.0, "y");
  data.yaw = rounded<std::int32_t>(pose.theta * kDegPerRad, "theta");
  data.xspeed = rounded<std::int32_t>(tv * 1000.0, "tv");
  data.yawspeed = rounded<std::int32_t>(rv * kDegPerRad, "rv");
  return data;
}

protocol::TruthData truth_of(const CarmenPose& pose) {
  protocol::TruthData data;
  data.px = rounded<std::int32_t>(pose.x * 1000.0, "x");
  data.py = rounded<std::int32_t>(pose.y * 1000.0, "y");
  data.pa = rounded<std::int32_t>(pose.theta * kDegPerRad, "theta");
  return data;
}

CarmenPose pose_of(std::int32_t x_mm, std::int32_t y_mm, std::int32_t yaw_deg) {
  return {x_mm / 1000.0, y_mm / 1000.0, yaw_deg / kDegPerRad};
}

// The laser index a CARMEN laser record becomes.
std::uint16_t laser_index(CarmenLaserKind kind) {
  switch (kind) {
    case CarmenLaserKind::kFlaser: return 0;
    case CarmenLaserKind::kRlaser: return 1;
    case CarmenLaserKind::kLaser3: return 2;
    case CarmenLaserKind::kLaser4: return 3;
    case CarmenLaserKind::kRawLaser1: return 0;
    case CarmenLaserKind::kRawLaser2: return 1;
    case CarmenLaserKind::kRawLaser3: return 2;
    case CarmenLaserKind::kRawLaser4: return 3;
    case CarmenLaserKind::kRobotLaser1: return 0;
    case CarmenLaserKind::kRobotLaser2: return 1;
  }
  return 0;
}

CarmenStamp stamp_of(const CarmenRecord& record) {
  return std::visit([](const auto& r) { return r.stamp; }, record);
}

}  // namespace

Message carmen_laser_to_player(const CarmenLaser& laser, std::uint16_t index, Timestamp server_time,
                               Timestamp data_time) {
  const std::size_t beams = laser.ranges.size();
  if (beams > protocol::kLaserMaxSamples) {
    throw std::invalid_argument("a scan of " + std::to_string(beams) + " beams exceeds the " +
                                std::to_string(protocol::kLaserMaxSamples) + " a Player laser scan holds");
  }
  protocol::LaserData scan;
  const double hundredths_per_rad = 100.0 * kDegPerRad;
  scan.min_angle = rounded<std::int16_t>(laser.config.start_angle * hundredths_per_rad, "start_angle");
  scan.resolution = rounded<std::uint16_t>(laser.config.angular_resolution * hundredths_per_rad,
                                           "angular_resolution");
  const double last = laser.config.start_angle +
                      laser.config.angular_resolution * static_cast<double>(beams == 0 ? 0 : beams - 1);
  scan.max_angle = rounded<std::int16_t>(last * hundredths_per_rad, "last beam angle");
  scan.range_count = static_cast<std::uint16_t>(beams);
  const double longest = beams == 0 ? 0.0 : *std::max_element(laser.ranges.begin(), laser.ranges.end());
  // The finest unit in which the longest reading fits 16 bits.
  scan.range_res = 0;
  for (const std::uint16_t range_res : {std::uint16_t{1}, std::uint16_t{10}, std::uint16_t{100}}) {
    if (std::round(longest * 1000.0 / range_res) <= std::numeric_limits<std::uint16_t>::max()) {
      scan.range_res = range_res;
      break;
    }
  }
  if (scan.range_res == 0) {
    throw std::invalid_argument("range " + std::to_string(longest) +
                                " m is beyond what a Player laser scan carries (6553.5 m)");
  }
  for (std::size_t i = 0; i < beams; ++i) {
    if (!(laser.ranges[i] >= 0)) {
      throw std::invalid_argument("range " + std::to_string(laser.ranges[i]) + " m is negative");
    }
    scan.ranges[i] = static_cast<std::uint16_t>(std::round(laser.ranges[i] * 1000.0 / scan.range_res));
  }
  return data_message(DeviceAddress{protocol::kLaserCode, index}, server_time, data_time, scan);
}

PlayerMessages carmen_to_player(const CarmenRecord& record) {
  const CarmenStamp stamp = stamp_of(record);
  PlayerMessages out;
  out.host = stamp.host;
  if (std::holds_alternative<CarmenParam>(record) || std::holds_alternative<CarmenTruePos>(record)) {
    return out;
  }
  const Timestamp server_time = to_timestamp(stamp.logger_timestamp);
  const Timestamp data_time = to_timestamp(stamp.ipc_timestamp);
  const DeviceAddress position{protocol::kPositionCode, 0};
  if (const auto* odometry = std::get_if<CarmenOdometry>(&record)) {
    out.messages.push_back(data_message(position, server_time, data_time,
                                        position_of(odometry->pose, odometry->tv, odometry->rv)));
    return out;
  }
  const auto& laser = std::get<CarmenLaser>(record);
  const std::uint16_t index = laser_index(laser.kind);
  out.messages.push_back(carmen_laser_to_player(laser, index, server_time, data_time));
  if (laser.robot_pose) {
    const double tv = laser.motion ? laser.motion->tv : 0.0;
    const double rv = laser.motion ? laser.motion->rv : 0.0;
    out.messages.push_back(data_message(position, server_time, data_time, position_of(*laser.robot_pose, tv, rv)));
  }
  if (laser.laser_pose) {
    out.messages.push_back(data_message(DeviceAddress{protocol::kTruthCode, index}, server_time, data_time,
                                        truth_of(*laser.laser_pose)));
  }
  return out;
}

bool PlayerToCarmen::feed(const Message& message, const std::string& host) {
  if (message.type() != protocol::MessageType::kData || message.device().index != 0) return false;
  const auto code = message.device().interface;
  const double server_time = message.time().seconds();
  const double data_time = message.timestamp().seconds();
  if (code == protocol::kPositionCode) {
    const auto data = protocol::decode<protocol::PositionData>(message.payload);
    const CarmenPose pose = pose_of(data.xpos, data.ypos, data.yaw);
    latest_robot_pose_ = pose;
    if (pending_ && !pending_->has_robot_pose && pending_->data_time == message.timestamp()) {
      pending_->laser.robot_pose = pose;
      pending_->has_robot_pose = true;
      return true;
    }
    flush_pending();
    CarmenOdometry odometry;
    odometry.pose = pose;
    odometry.tv = data.xspeed / 1000.0;
    odometry.rv = data.yawspeed / kDegPerRad;
    odometry.stamp = {data_time, host, server_time};
    records_.emplace_back(std::move(odometry));
    return true;
  }
  if (code == protocol::kTruthCode) {
    const auto data = protocol::decode<protocol::TruthData>(message.payload);
    const CarmenPose pose = pose_of(data.px, data.py, data.pa);
    latest_laser_pose_ = pose;
    if (pending_ && !pending_->has_laser_pose && pending_->data_time == message.timestamp()) {
      pending_->laser.laser_pose = pose;
      pending_->has_laser_pose = true;
    }
    return true;
  }
  if (code == protocol::kLaserCode) {
    flush_pending();
    const auto scan = protocol::decode<protocol::LaserData>(message.payload);
    PendingScan next;
    next.data_time = message.timestamp();
    next.laser.kind = CarmenLaserKind::kFlaser;
    next.laser.config = guess_carmen_laser_config(scan.range_count);
    next.laser.config_guessed = true;
    const double hundredths_per_rad = 100.0 * kDegPerRad;
    const auto guessed_min =
        static_cast<long>(std::lround(next.laser.config.start_angle * hundredths_per_rad));
    const auto guessed_resolution =
        static_cast<long>(std::lround(next.laser.config.angular_resolution * hundredths_per_rad));
    if (scan.range_count > 1 && (guessed_min != scan.min_angle || guessed_resolution != scan.resolution)) {
      ++layout_mismatches_;
    }
    next.laser.ranges.reserve(scan.range_count);
    for (std::size_t i = 0; i < scan.range_count; ++i) {
      next.laser.ranges.push_back(static_cast<double>(std::uint32_t{scan.ranges[i]} * scan.range_res) / 1000.0);
    }
    next.laser.stamp = {data_time, host, server_time};
    pending_ = std::move(next);
    return true;
  }
  return false;
}

void PlayerToCarmen::flush_pending() {
  if (!pending_) return;
  auto& laser = pending_->laser;
  if (!pending_->has_robot_pose) {
    if (!latest_robot_pose_) ++scans_without_pose_;
    laser.robot_pose = latest_robot_pose_.value_or(CarmenPose{});
  }
  if (!pending_->has_laser_pose) laser.laser_pose = latest_laser_pose_.value_or(*laser.robot_pose);
  records_.emplace_back(std::move(laser));
  pending_.reset();
}

void PlayerToCarmen::finish() { flush_pending(); }

std::vector<CarmenRecord> PlayerToCarmen::take_records() {
  std::vector<CarmenRecord> taken;
  taken.swap(records_);
  return taken;
}

}  // namespace playerkit::log
