#pragma once
// Options that belong to a robot rather than to one of its devices. In
// Player 1.5 a Pioneer's eleven devices are eleven sections, and the serial
// `port` may be written on any one of them (or on several, the same value):
//
//   position:0 ( driver "p2os_position" port "/dev/ttyUSB0" )
//   sonar:0    ( driver "p2os_sonar" )
//
// robot_option() finds it for every device of the family served on the same
// server port, so that all of them share one connection.

#include <initializer_list>
#include <string>
#include <string_view>

#include "core/driver_registry.hpp"

namespace playerkit::core {

struct RobotOption {
  std::string value;
  bool given = false;  // false: no section of the robot wrote it (value is the fallback)
};

// The value of option `name` written in any section of `context`'s robot:
// the devices on the same server port whose driver is one of
// `family_drivers`. Every section's value is read (and so marked used). Two
// different values are a config::ConfigError at the second, naming the first
// (1.5 silently took the last one and lost the other robot's devices).
RobotOption robot_option(const DriverContext& context,
                         std::initializer_list<std::string_view> family_drivers,
                         std::string_view name, std::string_view fallback);

}  // namespace playerkit::core
