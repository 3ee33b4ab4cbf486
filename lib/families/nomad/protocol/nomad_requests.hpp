#pragma once
// The requests the nomad driver sends and the state reply it reads
// (nomad.md §1.2, §1.3), as Nclient messages. Values are the robot's units:
// tenths of an inch, tenths of a degree, inches for ranges.

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "families/nomad/protocol/nclient_message.hpp"

namespace playerkit::hardware::nomad {

inline constexpr std::size_t kIrCount = 16;
inline constexpr std::size_t kSonarCount = 16;
// Words of a state reply without laser points (nomad.md §1.2).
inline constexpr std::size_t kStateWords = 49;
// The robot id CONNECT_ROBOT names: the library's only robot.
inline constexpr std::int32_t kRobotId = 1;
// What the reference asked of the robot at setup (nomad.md §1.2).
inline constexpr std::int32_t kCommandTimeoutSeconds = 5;
inline constexpr std::array<std::int32_t, 3> kSetupAccelerations{300, 300, 300};
inline constexpr std::array<std::int32_t, 3> kSetupSpeeds{200, 450, 450};

[[nodiscard]] Message connect_robot(std::int32_t client_pid);
// Every IR and sonar, the bumpers, configuration and velocities, compass
// and laser bits, no position-data attachments.
[[nodiscard]] Message sensor_mask();
[[nodiscard]] Message command_timeout(std::int32_t seconds);
[[nodiscard]] Message zero();
[[nodiscard]] Message accelerations(const std::array<std::int32_t, 3>& tenths);
[[nodiscard]] Message speeds(const std::array<std::int32_t, 3>& tenths);
// Translation in 0.1 in/s, steering and turret in 0.1 deg/s.
[[nodiscard]] Message velocity(std::int32_t translation, std::int32_t steering, std::int32_t turret);
[[nodiscard]] Message get_state();

// The robot's state as a STATE_MSG carries it.
struct RobotState {
  std::int32_t simulation_speed = 0;
  std::array<std::int32_t, kIrCount> ir{};        // inches
  std::array<std::int32_t, kSonarCount> sonar{};  // inches, 0..255
  std::int32_t bumpers = 0;                       // one bit a bumper
  std::int32_t x = 0;                             // 0.1 inch
  std::int32_t y = 0;                             // 0.1 inch
  std::int32_t steering = 0;                      // 0.1 degree
  std::int32_t turret = 0;                        // 0.1 degree
  std::int32_t translation_velocity = 0;          // 0.1 in/s
  std::int32_t steering_velocity = 0;             // 0.1 deg/s
  std::int32_t turret_velocity = 0;               // 0.1 deg/s
  std::int32_t motor_status = 0;
  std::int32_t laser_mode = 0;
  std::int32_t compass = 0;  // 0.1 degree
  std::int32_t error = 0;
  std::vector<std::int32_t> laser_points;  // pairs; none in this driver's mask
  std::int32_t controller_time = 0;
  std::int32_t cpu_voltage = 0;    // raw byte
  std::int32_t motor_voltage = 0;  // raw byte
  friend bool operator==(const RobotState&, const RobotState&) = default;
};

[[nodiscard]] Message state_reply(const RobotState& state);
// nullopt unless a STATE_MSG of at least 49 words whose laser count fits.
[[nodiscard]] std::optional<RobotState> parse_state(const Message& message);

// What the client library made of a reply: ERROR_MSG and type -1 are
// failures, anything else an answer (nomad.md §1.1).
[[nodiscard]] bool is_failure(const Message& reply);

}  // namespace playerkit::hardware::nomad
