#include "navigation_setup.hpp"

#include <stdexcept>
#include <string>

#include "config/config_file.hpp"
#include "drivers/amcl/amcl_options.hpp"
#include "drivers/vfh/vfh_options.hpp"
#include "drivers/wavefront/wavefront_options.hpp"

namespace playerkit::nav_bench {

namespace {

const config::Section& section_of(const config::ConfigFile& file, const std::string& driver) {
  for (const config::Section& section : file.sections()) {
    if (section.read_string("driver", "") == driver) return section;
  }
  throw std::runtime_error(file.filename() + ": no section with driver \"" + driver +
                           "\" (the loop needs amcl, vfh and wavefront)");
}

}  // namespace

NavigationSetup read_navigation_setup(const std::filesystem::path& config_file) {
  const config::ConfigFile file = config::ConfigFile::load(config_file);
  NavigationSetup setup;
  const drivers::AmclOptions localizer = drivers::read_amcl_options(section_of(file, "amcl"));
  setup.localizer = localizer.parameters;
  if (localizer.initial_pose) setup.initial_covariance = localizer.initial_pose->covariance;
  setup.laser_range_max = localizer.laser_range_max;
  setup.local_planner = drivers::vfh_driver::read_vfh_options(section_of(file, "vfh")).navigator;
  const auto global = drivers::wavefront_driver::read_wavefront_options(section_of(file, "wavefront"));
  setup.global_planner = global.planner;
  setup.waypoints.follower = global.follower;
  setup.waypoints.jump_distance = global.jump_distance;
  return setup;
}

}  // namespace playerkit::nav_bench
