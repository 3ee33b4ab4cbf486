#include "families/p2os/driver/robot_readings.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <type_traits>
#include <variant>

namespace playerkit::drivers::p2os {

namespace hw = hardware::p2os;

namespace {

constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;

int wheel_speed(std::int16_t raw, const hw::RobotParams& params) {
  return static_cast<int>(std::rint(raw * params.vel_conv_factor));
}

// Bumper switches 5 ... 1 of a SIP stall/bumper byte as five readings, as 1.5
// lists them (switch k+1 at index 4-k).
void put_switches(std::uint8_t stall_bumper_byte, std::array<std::uint8_t, 32>& bumpers, int first) {
  for (int i = 0; i < 5; ++i) {
    bumpers[static_cast<std::size_t>(first + i)] =
        static_cast<std::uint8_t>((stall_bumper_byte >> (5 - i)) & 0x01);
  }
}

}  // namespace

int whole_degrees(double radians) {
  int degrees = static_cast<int>(std::lround(radians * kDegreesPerRadian)) % 360;
  if (degrees < 0) degrees += 360;
  return degrees;
}

RobotReadings::RobotReadings(const hw::RobotParams& params) : params_(&params) {}

void RobotReadings::start_session(const hw::RobotParams& params) {
  params_ = &params;
  sip_.reset();
  ranges_.fill(0);
  compass_degrees_ = 0;
  gyro_rate_ = 0;
  blob_ = {};
  blob_color_ = 0;
}

void RobotReadings::take_sip(const hw::StandardSip& sip) {
  for (const hw::SonarReading& reading : sip.sonar) {
    if (reading.index >= params_->sonar_count || reading.index >= protocol::kSonarMaxSamples) {
      ++sonar_out_of_range_;
      continue;
    }
    const double millimetres = std::rint(reading.range * params_->range_conv_factor);
    ranges_[reading.index] = static_cast<std::uint16_t>(std::min(millimetres, 65535.0));
  }
  if (const auto degrees = hw::compass_degrees(sip.compass)) compass_degrees_ = *degrees;
  sip_ = sip;
}

void RobotReadings::take_gyro(const hw::GyroPacket& packet) {
  if (const auto rate = packet.average_rate()) gyro_rate_ = *rate;
}

void RobotReadings::take_cmucam(const hw::CmucamMessage& message) {
  std::visit(
      [this](const auto& m) {
        using Message = std::decay_t<decltype(m)>;
        if constexpr (std::is_same_v<Message, hw::CmucamTracking>) {
          blob_ = m;
        } else {
          blob_color_ = (std::uint32_t{m.red} << 16) | (std::uint32_t{m.green} << 8) | m.blue;
        }
      },
      message);
}

protocol::PositionData RobotReadings::position(const geometry::Pose2& pose) const {
  protocol::PositionData data;
  data.xpos = static_cast<std::int32_t>(std::lround(pose.x));
  data.ypos = static_cast<std::int32_t>(std::lround(pose.y));
  data.yaw = whole_degrees(pose.yaw);
  if (sip_) {
    const int left = wheel_speed(sip_->left_velocity, *params_);
    const int right = wheel_speed(sip_->right_velocity, *params_);
    data.xspeed = (left + right) / 2;
    data.yawspeed = static_cast<std::int32_t>(
        std::trunc((right - left) * params_->diff_conv_factor / 2.0 * kDegreesPerRadian));
    data.stall = (sip_->left_stalled() || sip_->right_stalled()) ? 1 : 0;
  }
  return data;
}

protocol::SonarData RobotReadings::sonar() const {
  protocol::SonarData data;
  data.range_count = static_cast<std::uint16_t>(
      std::min<int>(params_->sonar_count, static_cast<int>(protocol::kSonarMaxSamples)));
  for (std::size_t i = 0; i < data.range_count; ++i) data.ranges[i] = ranges_[i];
  return data;
}

protocol::GripperData RobotReadings::gripper() const {
  protocol::GripperData data;
  if (sip_) {
    data.state = sip_->gripper_state;
    data.beams = sip_->digital_in;
  }
  return data;
}

protocol::PowerData RobotReadings::power() const {
  protocol::PowerData data;
  if (sip_) data.charge = sip_->battery;
  return data;
}

protocol::BumperData RobotReadings::bumper() const {
  protocol::BumperData data;
  data.bumper_count = 10;
  if (sip_) {
    put_switches(sip_->stall_bumpers_high, data.bumpers, 0);  // front
    put_switches(sip_->stall_bumpers_low, data.bumpers, 5);   // rear
  }
  return data;
}

protocol::AioData RobotReadings::aio() const {
  protocol::AioData data;
  data.count = 1;
  if (sip_) data.anin[0] = sip_->analog;
  return data;
}

protocol::DioData RobotReadings::dio() const {
  protocol::DioData data;
  data.count = 8;
  if (sip_) data.digin = sip_->digital_in;
  return data;
}

protocol::PositionData RobotReadings::compass() const {
  protocol::PositionData data;
  data.yaw = compass_degrees_;
  return data;
}

protocol::PositionData RobotReadings::gyro() const {
  protocol::PositionData data;
  data.yawspeed = gyro_rate_;
  return data;
}

protocol::BlobfinderData RobotReadings::blobfinder() const {
  protocol::BlobfinderData data;
  data.width = kCmucamImageWidth;
  data.height = kCmucamImageHeight;
  const std::uint32_t area = blob_.area();
  data.header[0].index = 0;
  data.header[0].num = area > 1 ? 1 : 0;
  // 1.5 sends the whole struct, every blob slot included.
  data.blobs.resize(protocol::kBlobfinderMaxBlobs);
  protocol::BlobfinderBlob& blob = data.blobs[0];
  blob.color = blob_color_;
  blob.area = area;
  blob.x = blob_.mx;
  blob.y = blob_.my;
  blob.left = blob_.x1;
  blob.right = blob_.x2;
  blob.top = blob_.y1;
  blob.bottom = blob_.y2;
  blob.range = blob_.confidence;
  return data;
}

}  // namespace playerkit::drivers::p2os
