#pragma once
// The options of the segwayrmp drivers (segwayrmp.md §4 and what a CAN
// port adds). As in 1.5, where one hidden RMP device read them, they belong
// to the robot: written on any one of its sections (segwayrmp, rmpposition,
// rmppower), the same value wherever written twice.

#include <chrono>
#include <string>

#include "core/driver_registry.hpp"
#include "core/option_schema.hpp"

namespace playerkit::drivers::segwayrmp {

enum class CanIo { socketcan, slcan };

struct RmpSettings {
  CanIo canio = CanIo::socketcan;
  std::string device = "can0";        // socketcan: the network interface
  std::string port = "/dev/ttyUSB0";  // slcan: the adapter's serial port or tcp:HOST:PORT
  int baudrate = 115200;              // slcan: the serial line's speed
  int bitrate = 500000;               // the CAN bus's, bit/s
  double max_xspeed = 500;            // mm/s, absolute
  double max_yawspeed = 40;           // deg/s, absolute
  double max_xaccel = 0;              // mm/s², 0: none
  double max_yawaccel = 0;            // deg/s², 0: none
  std::chrono::milliseconds command_timeout{400};
  std::chrono::milliseconds status_timeout{1000};

  // "socketcan:can0", "slcan:/dev/ttyUSB0": names the bus in keys and logs.
  [[nodiscard]] std::string bus_name() const;
};

[[nodiscard]] const core::OptionSchema& rmp_option_schema();

// Throws config::ConfigError at the value: canio "kvaser" with the way out,
// a bit rate slcan cannot set, two sections disagreeing.
[[nodiscard]] RmpSettings read_rmp_settings(const core::DriverContext& context);

}  // namespace playerkit::drivers::segwayrmp
