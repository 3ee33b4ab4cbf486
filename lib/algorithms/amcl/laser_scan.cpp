#include "algorithms/amcl/laser_scan.hpp"

#include <cmath>
#include <stdexcept>

namespace playerkit::amcl {

bool usable_reading(const LaserScan& scan, std::size_t index) {
  const double range = scan.ranges[index];
  return std::isfinite(scan.bearings[index]) && !std::isnan(range) && range >= scan.min_range;
}

void prepare_beams(const LaserScan& scan, std::size_t max_beams, PreparedBeams& out,
                   const std::vector<unsigned char>* left_out) {
  if (scan.ranges.size() != scan.bearings.size()) {
    throw std::invalid_argument("LaserScan: ranges and bearings differ in size");
  }
  if (left_out != nullptr && left_out->size() != scan.ranges.size()) {
    throw std::invalid_argument("prepare_beams: left_out differs in size from the scan");
  }
  const auto usable = [&](std::size_t i) {
    return usable_reading(scan, i) && (left_out == nullptr || (*left_out)[i] == 0);
  };
  out.max_range = scan.max_range;
  out.sensor_pose = scan.sensor_pose;
  out.ranges.clear();
  out.robot_angle.clear();
  out.cos_angle.clear();
  out.sin_angle.clear();
  out.end_x.clear();
  out.end_y.clear();
  out.no_return.clear();

  const auto keep = [&](std::size_t i) {
    const bool no_return = scan.ranges[i] >= scan.max_range;
    const double range = no_return ? scan.max_range : scan.ranges[i];
    const double angle = scan.sensor_pose.yaw + scan.bearings[i];
    const double c = std::cos(angle), s = std::sin(angle);
    out.ranges.push_back(range);
    out.robot_angle.push_back(angle);
    out.cos_angle.push_back(c);
    out.sin_angle.push_back(s);
    out.end_x.push_back(scan.sensor_pose.x + range * c);
    out.end_y.push_back(scan.sensor_pose.y + range * s);
    out.no_return.push_back(no_return ? 1 : 0);
  };
  // Spread the kept beams over the usable readings, so invalid readings do
  // not eat into the budget.
  for_each_spread_reading(scan.ranges.size(), max_beams, usable, keep);
}

}  // namespace playerkit::amcl
