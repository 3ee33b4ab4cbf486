#pragma once
// What a client program of any robot base does in the end-to-end tests:
// switch the motors on, then drive a square — four sides, each followed by
// a quarter turn left — closing each leg on the odometry it reads, with a
// proportional slow-down. Every message read on the way is handed to an
// observer too (laser scans, GPS fixes), so a test checks what it carries.
//
//   SquareSettings square{.side = 0.3, .top_speed = 0.1};
//   const SquareDrive drive = drive_square(client, square, [&](const protocol::Message& m) { ... });
//   ASSERT_TRUE(drive.finished) << drive.failure;

#include <chrono>
#include <functional>
#include <optional>
#include <string>

#include "client/client.hpp"
#include "client/typed/position.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/message.hpp"

namespace playerkit::hardware_test {

struct SquareSettings {
  protocol::DeviceAddress position{protocol::kPositionCode, 0};
  double side = 1.0;             // m
  double top_speed = 0.5;        // m/s, far from the end of a side
  double slowest_speed = 0.05;   // m/s, near it: what the robot still moves at
  double top_turn_rate = 1.2;    // rad/s
  double slowest_turn_rate = 0.1;
  double distance_tolerance = 0.005;  // m: a side ends this close to its length
  double heading_tolerance = 0.01;    // rad
  std::chrono::seconds leg_limit{15};  // for each side and each turn
  // Ask for motor power first (the Pioneer's motors start disabled); robots
  // whose motors have no switch may ignore the request, but must answer.
  bool enable_motors = true;
};

struct SquareDrive {
  bool finished = false;
  std::string failure;  // which leg timed out, or what the server refused
  std::optional<client::PositionState> odometry;  // the last read
};

// Drives the square through `client` (access to the position device already
// granted), stops the robot and reads what arrives for half a second more.
SquareDrive drive_square(client::Client& client, const SquareSettings& settings,
                         const std::function<void(const protocol::Message&)>& observe = {});

// A velocity command in SI units to the position device.
void command_velocity(client::Client& client, protocol::DeviceAddress position, double speed, double turn_rate);

}  // namespace playerkit::hardware_test
