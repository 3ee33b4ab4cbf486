#pragma once
// Options that belong to a robot rather than to one of its devices. In
// Player 1.5 a Pioneer's eleven devices are eleven sections, and the serial
// `port` may be written on any one of them (or on several, the same value):
//
//   position:0 ( driver "p2os_position" port "/dev/ttyUSB0" )
//   sonar:0    ( driver "p2os_sonar" )
//
// robot_value() finds it for every device of the family served on the same
// server port, so that all of them share one connection.

#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "core/driver_registry.hpp"

namespace playerkit::core {

// A section of the robot, and the driver declared on it.
struct RobotSection {
  const config::Section* section;
  std::string driver;
};

// The sections of `context`'s robot (the devices on the same server port
// whose driver is one of `family_drivers`) that write `name`, in config order.
std::vector<RobotSection> robot_sections_with(const DriverContext& context,
                                              std::span<const std::string_view> family_drivers,
                                              std::string_view name);

// A config::ConfigError at `second`'s value of `name`, naming both values
// as written and where the first is.
[[noreturn]] void throw_robot_values_differ(const RobotSection& second, const RobotSection& first,
                                            std::string_view name);

// `read(section, driver)` on every section of the robot that writes `name`
// (so each is checked, and marked used); nullopt when none does. Two
// different values are a config::ConfigError at the second, naming the first
// (1.5 silently took the last one and lost the other robot's devices).
template <class Read>
auto robot_value(const DriverContext& context, std::span<const std::string_view> family_drivers,
                 std::string_view name, Read read)
    -> std::optional<std::invoke_result_t<Read&, const config::Section&, const std::string&>> {
  std::optional<std::invoke_result_t<Read&, const config::Section&, const std::string&>> value;
  std::optional<RobotSection> first;
  for (const RobotSection& place : robot_sections_with(context, family_drivers, name)) {
    auto here = read(*place.section, place.driver);
    if (!value) {
      value = std::move(here);
      first = place;
    } else if (!(here == *value)) {
      throw_robot_values_differ(place, *first, name);
    }
  }
  return value;
}

struct RobotOption {
  std::string value;
  bool given = false;  // false: no section of the robot wrote it (value is the fallback)
};

// robot_value() of a string option, `fallback` when no section writes it.
RobotOption robot_option(const DriverContext& context,
                         std::initializer_list<std::string_view> family_drivers,
                         std::string_view name, std::string_view fallback);

}  // namespace playerkit::core
