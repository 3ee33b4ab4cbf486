#pragma once
// The options of the p2os drivers (p2os.md §4.1, manual table 7.2), declared
// once in schemas (core::OptionSchema) that the reader, `player-serve
// --check`, `player-drivers info` and the README's table all use.
//
// Robot options belong to the robot, not to one device: in 1.5's form they
// may be written on any one of its sections (or on several, the same value
// each time). A value that differs between two sections is an error at the
// second (1.5 silently took the last one).
//
//   port             port    "/dev/ttyS0"  the serial port, or tcp:HOST:PORT
//   radio            int     0             non-zero: radio-modem dialogue first
//   joystick         int     0             non-zero: JOYDRIVE 1 (joystick drives)
//   connect_timeout  float   5 s           handshake budget at setup (playerkit)
//   sip_timeout      float   2 s           silence that means the robot is gone (playerkit)
//
// p2os_position's own: max_xspeed (int mm/s, 500), max_yawspeed (int
// deg/s, 100), use_vel_band (int, 0).

#include <chrono>
#include <string>
#include <string_view>

#include "core/driver_registry.hpp"
#include "core/option_schema.hpp"
#include "families/p2os/driver/motor_commands.hpp"
#include "families/p2os/driver/p2os_role.hpp"

namespace playerkit::drivers::p2os {

inline constexpr std::string_view kDefaultP2osPort = "/dev/ttyS0";

struct RobotLinkOptions {
  std::string port{kDefaultP2osPort};
  bool radio = false;
  bool joystick = false;
  std::chrono::milliseconds connect_timeout{5000};
  std::chrono::milliseconds sip_timeout{2000};

  friend bool operator==(const RobotLinkOptions&, const RobotLinkOptions&) = default;
};

// The robot options, accepted on every p2os section.
const core::OptionSchema& robot_link_schema();
// The options of `role`'s section: the robot's, then (p2os_position) the motors'.
const core::OptionSchema& p2os_option_schema(P2osRole role);

// Reads the robot options from every section of `context`'s robot. Throws
// config::ConfigError at the offending value.
RobotLinkOptions read_robot_link_options(const core::DriverContext& context);

// p2os_position's own options, from its section.
MotorLimits read_motor_limits(const core::DriverContext& context);

// The key under which the robot's connection is shared: "p2os /dev/ttyS0".
std::string connection_key(const RobotLinkOptions& options);

}  // namespace playerkit::drivers::p2os
