#pragma once
// What the closed loop is made of, read from a Player configuration file the
// way player-serve reads it: the amcl, vfh and wavefront sections' options,
// each through its driver's own reader, so the benchmark runs the shipped
// configuration (data/config/nav-sim.cfg) and not numbers of its own.

#include <filesystem>
#include <optional>

#include "algorithms/amcl/amcl_filter.hpp"
#include "algorithms/vfh/vfh_navigator.hpp"
#include "algorithms/wavefront/wavefront_navigator.hpp"

namespace playerkit::nav_bench {

struct NavigationSetup {
  amcl::AmclParameters localizer;
  // The spread the filter starts with around the robot's true start; the
  // section's init_pose itself is ignored (each world puts its robot elsewhere).
  Eigen::Matrix3d initial_covariance = Eigen::Matrix3d::Identity();
  double laser_range_max = 8.0;  // m
  vfh::NavigatorSettings local_planner;
  wavefront::PlannerParameters global_planner;
  wavefront::NavigatorSettings waypoints;
};

// Throws config::ConfigError (file:line:col) for a bad section and
// std::runtime_error naming the driver when one of the three is missing.
NavigationSetup read_navigation_setup(const std::filesystem::path& config_file);

}  // namespace playerkit::nav_bench
