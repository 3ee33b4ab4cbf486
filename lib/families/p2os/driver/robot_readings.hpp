#pragma once
// What the robot has reported in this session, as the eleven devices show
// it (p2os.md §3): the latest SIP, each sonar's last range, the compass kept
// over its "no reading" bytes, the gyro rate, the CMUcam blob. Pure: packets
// in, Player structs out.

#include <array>
#include <cstdint>
#include <optional>

#include "algorithms/geometry/pose2.hpp"
#include "families/p2os/protocol/aux_serial.hpp"
#include "families/p2os/protocol/gyro_packet.hpp"
#include "families/p2os/protocol/robot_params.hpp"
#include "families/p2os/protocol/sip.hpp"
#include "protocol/messages/aio.hpp"
#include "protocol/messages/blobfinder.hpp"
#include "protocol/messages/bumper.hpp"
#include "protocol/messages/dio.hpp"
#include "protocol/messages/gripper.hpp"
#include "protocol/messages/position.hpp"
#include "protocol/messages/power.hpp"
#include "protocol/messages/sonar.hpp"

namespace playerkit::drivers::p2os {

// The CMUcam's image, as 1.5 reports it.
inline constexpr std::uint16_t kCmucamImageWidth = 80;
inline constexpr std::uint16_t kCmucamImageHeight = 143;

class RobotReadings {
 public:
  explicit RobotReadings(const hardware::p2os::RobotParams& params);

  // A new session: everything is forgotten (as 1.5 did at every connect).
  void start_session(const hardware::p2os::RobotParams& params);

  void take_sip(const hardware::p2os::StandardSip& sip);
  void take_gyro(const hardware::p2os::GyroPacket& packet);
  void take_cmucam(const hardware::p2os::CmucamMessage& message);

  // Sonar readings whose transducer number is not below the row's SonarNum
  // (1.5 wrote them past its array, quirk 12); counted, not stored.
  [[nodiscard]] std::uint64_t sonar_out_of_range() const { return sonar_out_of_range_; }
  [[nodiscard]] const std::optional<hardware::p2os::StandardSip>& sip() const { return sip_; }

  // p2os_position: `pose` is the odometry (mm, mm, rad); speeds from the SIP.
  [[nodiscard]] protocol::PositionData position(const geometry::Pose2& pose) const;
  [[nodiscard]] protocol::SonarData sonar() const;
  [[nodiscard]] protocol::GripperData gripper() const;
  [[nodiscard]] protocol::PowerData power() const;
  [[nodiscard]] protocol::BumperData bumper() const;
  [[nodiscard]] protocol::AioData aio() const;
  [[nodiscard]] protocol::DioData dio() const;
  // p2os_compass: only yaw, the compass heading in degrees.
  [[nodiscard]] protocol::PositionData compass() const;
  // p2os_gyro: only yawspeed, the raw averaged rate (0 ... 1023, 512 at rest).
  [[nodiscard]] protocol::PositionData gyro() const;
  // p2os_cmucam: the whole 7172-byte struct, one blob on channel 0.
  [[nodiscard]] protocol::BlobfinderData blobfinder() const;

 private:
  const hardware::p2os::RobotParams* params_;
  std::optional<hardware::p2os::StandardSip> sip_;
  std::array<std::uint16_t, protocol::kSonarMaxSamples> ranges_{};  // mm
  std::uint64_t sonar_out_of_range_ = 0;
  int compass_degrees_ = 0;
  int gyro_rate_ = 0;
  hardware::p2os::CmucamTracking blob_;
  std::uint32_t blob_color_ = 0;  // 0x00RRGGBB
};

// Degrees in [0, 360) from radians, rounded.
int whole_degrees(double radians);

}  // namespace playerkit::drivers::p2os
