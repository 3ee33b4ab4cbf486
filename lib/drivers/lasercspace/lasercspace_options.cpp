#include "drivers/lasercspace/lasercspace_options.hpp"

#include "core/option_reader.hpp"

namespace playerkit::drivers::lasercspace {

const core::OptionSchema& lasercspace_option_schema() {
  static const core::OptionSchema schema{
      core::OptionSpec::integer("laser", 0, 0, 65535).doc("index of the laser to read, on the same port"),
      core::OptionSpec::length("radius", 0.5, 0.0, 100.0).unit("m").doc("the robot's radius"),
      core::OptionSpec::integer("step", 1, 1, 401).doc("only every step-th return counts as an obstacle (faster, coarser)"),
  };
  return schema;
}

LaserCspaceOptions read_lasercspace_options(const config::Section& section) {
  const core::OptionReader options(section, "lasercspace", lasercspace_option_schema());
  return {.laser_index = options.integer("laser"),
          .radius = options.length("radius"),
          .obstacle_stride = options.integer("step")};
}

}  // namespace playerkit::drivers::lasercspace
