#pragma once
// How an emulated Pioneer is built: which robot it claims to be, where it
// stands, how wrong its odometry is, what world it drives in.

#include "algorithms/geometry/pose2.hpp"
#include "algorithms/grid/occupancy_grid.hpp"
#include "emulators/device_emulator.hpp"
#include "emulators/mobile_base/odometry_error.hpp"
#include "families/p2os/protocol/aux_serial.hpp"

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>

namespace playerkit::emulators {

struct P2osEmulatorOptions {
  // A subclass of the parameter table (families/p2os/protocol/robot_params.hpp), any
  // case; its row gives the SYNC2 strings, conversions and sonar ring.
  std::string subclass = "p3dx";
  std::string robot_name = "playerkit";  // at most 19 characters
  geometry::Pose2 initial_pose{};        // world frame, metres and radians
  mobile_base::OdometryError odometry_error{};
  double battery_volts = 12.5;
  // The world: sonars are ray-cast in it and the robot stalls against its
  // occupied cells. Not owned; may be null (open space).
  const grid::OccupancyGrid* map = nullptr;
  double sonar_max_range = 5.0;  // metres; also every reading without a map
  // Readings per SIP, cycling through the ring; 0 = every transducer.
  int sonars_per_sip = 0;
  // Real controllers poll their sonars from power-on; SONAR 0/1 switch them.
  bool sonar_on_at_open = true;
  // Radius of the round footprint that stalls against the map, metres;
  // unset: the row's Radius.
  std::optional<double> footprint_radius;
  Duration sip_period = std::chrono::milliseconds(100);
  // Motion is integrated in steps no longer than this (>= 100 Hz).
  Duration motion_step = std::chrono::milliseconds(10);
  // Stop when no packet arrived for this long (P2OS's watchdog); unset: off.
  std::optional<Duration> watchdog = std::chrono::seconds(2);
  // 0: the line speed is ignored (a pty). Otherwise the robot listens only
  // at this baud and bytes the host sent at another speed are line noise.
  int model_baud = 0;
  bool has_gripper = true;
  Duration gripper_travel_time = std::chrono::milliseconds(1500);  // full stroke
  std::uint8_t digital_inputs = 0;  // DIGIN bits 6-7 with a gripper, all 8 without
  std::uint8_t analog_input = 0;    // ANALOG
  std::uint8_t analog_port = 1;     // TIMER low byte
  // A CMUcam on AUX2 answering GETAUX2; with no blob it reports an empty one.
  bool has_cmucam = true;
  std::optional<hardware::p2os::CmucamTracking> cmucam_blob;
};

}  // namespace playerkit::emulators
