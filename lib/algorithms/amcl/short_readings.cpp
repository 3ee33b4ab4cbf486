#include "algorithms/amcl/short_readings.hpp"

#include <algorithm>
#include <cmath>

namespace playerkit::amcl {

ReadingClassifier::ReadingClassifier(const grid::OccupancyGrid& map)
    : map_(map), caster_(map, grid::RayStop::occupied_or_unknown) {}

ReadingFit ReadingClassifier::classify(const geometry::Pose2& sensor, double angle, double range,
                                       const ReadingMargins& margins) const {
  const double reach = range + margins.short_of_map;
  const Eigen::Vector2d from = sensor.translation();
  const Eigen::Vector2d direction(std::cos(angle), std::sin(angle));
  if (!map_.contains(map_.world_to_cell(from))) return ReadingFit::fits;
  const double met = caster_.range(from, direction, reach);
  if (met >= reach) {
    // Nothing but free cells out to the reach, unless the ray left the map
    // first (the caster answers that alike): beyond the edge is unknown.
    const Eigen::Vector2i end = map_.world_to_cell(from + reach * direction);
    return map_.contains(end) ? ReadingFit::short_of_map : ReadingFit::fits;
  }
  // The cell the ray stopped in: a hair past where it entered it.
  const Eigen::Vector2i stop = map_.world_to_cell(from + (met + 1e-6 * map_.resolution()) * direction);
  const bool occupied = map_.contains(stop) && map_.at(stop) == grid::CellState::occupied;
  return occupied && met < range - margins.through_wall ? ReadingFit::through_wall : ReadingFit::fits;
}

BeamFits ReadingClassifier::classify_beams(const geometry::Pose2& robot, const PreparedBeams& beams,
                                          const ReadingMargins& margins) const {
  const geometry::Pose2 sensor = robot.compose(beams.sensor_pose);
  BeamFits fits;
  for (std::size_t b = 0; b < beams.size(); ++b) {
    if (beams.no_return[b] != 0) continue;
    ++fits.returned;
    switch (classify(sensor, robot.yaw + beams.robot_angle[b], beams.ranges[b], margins)) {
      case ReadingFit::short_of_map: ++fits.short_of_map; break;
      case ReadingFit::through_wall: ++fits.through_wall; break;
      case ReadingFit::fits: break;
    }
  }
  return fits;
}

std::size_t ReadingClassifier::mark_short_readings(const geometry::Pose2& robot, const LaserScan& scan,
                                                   const ReadingMargins& margins, std::size_t most_checked,
                                                   std::vector<unsigned char>& out) const {
  const geometry::Pose2 sensor = robot.compose(scan.sensor_pose);
  const std::size_t readings = std::min(scan.ranges.size(), scan.bearings.size());
  out.assign(scan.ranges.size(), 1);
  std::size_t short_count = 0;
  const auto usable = [&](std::size_t i) { return usable_reading(scan, i); };
  const auto check = [&](std::size_t i) {
    const double range = scan.ranges[i];
    const bool is_short = range < scan.max_range &&
                          classify(sensor, sensor.yaw + scan.bearings[i], range, margins) ==
                              ReadingFit::short_of_map;
    out[i] = is_short ? 1 : 0;
    short_count += is_short ? 1 : 0;
  };
  for_each_spread_reading(readings, most_checked, usable, check);
  return short_count;
}

}  // namespace playerkit::amcl
