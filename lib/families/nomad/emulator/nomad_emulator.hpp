#pragma once
// An emulated Nomad 200 behind Nomadic's server, written from nomad.md §6
// ("what a faithful emulator must do"), so that Player 1.5's nomad driver
// (built 32-bit, as it must be) works against it unmodified:
//
//  * Nclient messages in lock-step: each whole request gets one reply after
//    `reply_delay` (the real server's pacing of a client that never sleeps);
//  * CONNECT_ROBOT: type 102, one word, the robot's server port (non-zero);
//    every other request: a 49-word STATE_MSG with no laser points;
//  * synchro drive: VM sets the translational velocity (0.1 in/s) and the
//    steering and turret rates (0.1 deg/s); the wheels travel along the
//    steering angle; ZR zeroes position and both angles; CONF_TM stops the
//    robot when no VM came for that many seconds;
//  * 16 sonars (inches, at most 255) and 16 infrared sensors (inches, at
//    most `ir_range`) on the turret, i at i x 22.5 degrees, seeing the map;
//    the body stops against a wall with the bumper bit facing it set.
//
// The reported odometry carries the configured error; the true pose (for a
// carried laser, world_pose(), and the sensors) does not.

#include <array>
#include <cstdint>
#include <deque>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "emulators/device_emulator.hpp"
#include "emulators/mobile_base/odometry_error.hpp"
#include "emulators/mobile_base/range_ring.hpp"
#include "families/nomad/protocol/nclient_message.hpp"
#include "families/nomad/protocol/nomad_requests.hpp"

namespace playerkit::grid {
class OccupancyGrid;
}

namespace playerkit::emulators {

struct NomadEmulatorOptions {
  Duration reply_delay = std::chrono::milliseconds(20);
  geometry::Pose2 start_pose;  // in the map: m, m, rad (the steering and turret angle)
  mobile_base::OdometryError odometry_error;
  // The radius the reference driver gave in its geometry (nomad.md §2.2),
  // so that what the emulated robot touches and sees agrees with it.
  double body_radius = 0.4;         // m: the bumper ring
  double sensor_ring_radius = 0.4;  // m: sonars and infrared on the turret's rim
  int ir_range_inches = 36;
  std::int32_t robot_server_port = 7020;  // what CONNECT_ROBOT answers
  const grid::OccupancyGrid* map = nullptr;  // not owned
};

class NomadEmulator final : public DeviceEmulator {
 public:
  explicit NomadEmulator(NomadEmulatorOptions options = {});

  void receive(std::span<const std::uint8_t> bytes, Duration now, int host_baud) override;
  void advance(Duration now) override;
  [[nodiscard]] Duration next_deadline() const override;
  std::vector<Telegram> take_output() override;
  void host_disconnected(Duration now) override;
  [[nodiscard]] std::optional<geometry::Pose2> world_pose() const override { return true_pose_; }
  [[nodiscard]] std::string describe() const override;

  // For tests.
  [[nodiscard]] hardware::nomad::RobotState state() const;
  [[nodiscard]] const geometry::Pose2& true_pose() const { return true_pose_; }
  [[nodiscard]] std::uint64_t requests() const { return requests_; }
  [[nodiscard]] std::uint64_t requests_of(std::int16_t type) const;
  [[nodiscard]] bool connected() const { return connected_; }

 private:
  struct PendingReply {
    Duration due;
    std::optional<hardware::nomad::Message> reply;  // none: the state when it leaves
  };
  void handle(const hardware::nomad::Message& request, Duration now);
  void send_due_replies();
  void move(double seconds);
  void stop_motion();
  void sense(hardware::nomad::RobotState& state) const;
  [[nodiscard]] bool touches_wall(const geometry::Pose2& pose, std::int32_t& bumpers) const;

  const NomadEmulatorOptions options_;
  const mobile_base::RangeRing ring_;  // sonars and infrared share the turret's rim
  std::mt19937_64 noise_;
  std::vector<std::uint8_t> input_;
  std::deque<PendingReply> pending_;
  std::vector<Telegram> output_;
  Duration now_{};
  bool connected_ = false;

  // Motion, in the robot's units per second.
  std::int32_t translation_velocity_ = 0;  // 0.1 in/s
  std::int32_t steering_velocity_ = 0;     // 0.1 deg/s
  std::int32_t turret_velocity_ = 0;       // 0.1 deg/s
  Duration command_timeout_{};             // 0: none
  Duration last_velocity_command_{};
  geometry::Pose2 true_pose_;  // m, m, rad: yaw is the steering angle
  double true_turret_ = 0.0;   // rad, in the map
  // Odometry since the last ZR: 0.1 inch and 0.1 degree, kept fractional.
  double odometry_x_ = 0.0;
  double odometry_y_ = 0.0;
  double odometry_steering_ = 0.0;
  double odometry_turret_ = 0.0;
  std::int32_t bumpers_ = 0;
  std::array<std::int32_t, 3> accelerations_{};
  std::array<std::int32_t, 3> speeds_{};
  std::uint64_t requests_ = 0;
  std::array<std::uint64_t, 128> requests_by_type_{};
};

}  // namespace playerkit::emulators
