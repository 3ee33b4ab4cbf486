#pragma once
// The Vector Field Histogram's settings (vfh.md §3), in SI units. The
// defaults are Player 1.5's.

#include <numbers>

namespace playerkit::vfh {

struct VfhParameters {
  double cell_size = 0.1;             // m, of the histogram grid
  int window_diameter = 61;           // cells across the square window around the robot
  int sector_angle = 5;               // degrees a sector spans; divides 360
  double robot_radius = 0.25;         // m
  double safety_distance = 0.1;       // m kept beyond the radius
  double max_speed = 0.2;             // m/s
  double max_turn_rate = 40 * std::numbers::pi / 180;  // rad/s
  double min_turn_rate = 10 * std::numbers::pi / 180;  // rad/s: slower turns in place do not move a robot
  double free_space_cutoff = 2.0e6;   // a sector's histogram below it is free...
  double obstacle_cutoff = 2.0e6;     // ...above it blocked; between, as it was
  double weight_desired_direction = 5.0;
  double weight_current_direction = 3.0;
  // Beyond 1.5: the speed falls off to 0 as the free distance along the
  // chosen direction falls to `stop_distance` past the robot's radius and
  // safety distance, reaching max_speed at `stop_distance + slow_down_distance`.
  double stop_distance = 0.05;        // m
  double slow_down_distance = 1.5;    // m: about where the histogram blocks at the defaults
  double acceleration = 0.2;          // m/s² of the speed ramp (1.5: 20 mm/s a cycle)
};

// Throws std::invalid_argument naming the first bad value.
void validate(const VfhParameters& parameters);

}  // namespace playerkit::vfh
