#pragma once
// What an emulated SICK laser sees and how it is set up: the world (a map,
// reflectors), where the laser is in it, how it measures, and its power-up
// state. Shared by SickLms200Emulator and SickPlsEmulator.

#include "algorithms/geometry/pose2.hpp"
#include "algorithms/grid/occupancy_grid.hpp"
#include "algorithms/grid/ray_cast.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace playerkit::emulators {

// A surface that returns a reflector level (retro-reflective tape): a
// segment in the world frame. It is seen where a beam meets it before, or on,
// the map's wall (within a cell and a half, so tape drawn on a wall's cells
// counts); the LMS reports `level` in bits 13-15 in measuring mode 0x01.
struct SickReflector {
  Eigen::Vector2d from = Eigen::Vector2d::Zero();
  Eigen::Vector2d to = Eigen::Vector2d::Zero();
  std::uint8_t level = 7;  // 1..7
};

struct SickEmulatorOptions {
  // The world. Read once at construction (the emulator keeps a distance map
  // of it, not the pointer). Null: no walls, every beam reads
  // range_without_map_m (reflectors are still seen).
  const grid::OccupancyGrid* map = nullptr;
  // Which cells a beam stops at. A laser sees only things, so unknown cells
  // are see-through by default (Player's map_calc_range stops at them).
  grid::RayStop ray_stop = grid::RayStop::occupied;

  // The laser's pose in the world frame. pose_source, when set, is asked at
  // every scan instead (a laser on an emulated robot).
  geometry::Pose2 pose{};
  std::function<geometry::Pose2()> pose_source{};

  // The longest range measured, in metres. Unset: all the unit can encode,
  // 8191 steps (8.191 m in mm, 81.91 m in cm). A beam that meets nothing
  // reads the maximum.
  std::optional<double> max_range_m{};
  // What every beam reads without a map. Unset: the maximum.
  std::optional<double> range_without_map_m{};

  // Gaussian range noise on every return (not on no-return readings).
  double range_noise_sigma_m = 0.0;
  std::uint64_t noise_seed = 1;

  std::vector<SickReflector> reflectors{};

  // The type text of the BA reply (LMS 200 only), at most 20 characters,
  // padded with spaces to 20. Unset: "LMS200;30106".
  std::optional<std::string> type{};

  // The line speed at power-up (9600 on both real devices).
  int power_up_baud = 9600;
  // Treat bytes the host sent at another speed than the device's as line
  // noise (sicklms200.md §6 point 13). host_baud 0 (unknown, TCP) is always
  // accepted.
  bool model_baud_rates = true;
  // Send the ACK byte 0x06 before every reply, as the real devices do.
  bool send_ack = true;
};

}  // namespace playerkit::emulators
