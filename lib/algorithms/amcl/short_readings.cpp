#include "algorithms/amcl/short_readings.hpp"

#include "algorithms/grid/grid_traversal.hpp"

#include <algorithm>
#include <cmath>

namespace playerkit::amcl {

ReadingFit classify_reading(const grid::OccupancyGrid& map, const geometry::Pose2& sensor,
                            double angle, double range, const ReadingMargins& margins) {
  const double reach = range + margins.short_of_map;
  const double inverse_resolution = 1.0 / map.resolution();
  const Eigen::Vector2d from = (sensor.translation() - map.origin()) * inverse_resolution;
  const Eigen::Vector2d to =
      from + (reach * inverse_resolution) * Eigen::Vector2d(std::cos(angle), std::sin(angle));
  ReadingFit fit = ReadingFit::short_of_map;
  grid::detail::traverse_segment(from, to, [&](const Eigen::Vector2i& cell, double entry) {
    const bool inside = map.contains(cell);
    const grid::CellState state = inside ? map.at(cell) : grid::CellState::unknown;
    if (state == grid::CellState::free) return true;
    const bool through = state == grid::CellState::occupied && entry * reach < range - margins.through_wall;
    fit = through ? ReadingFit::through_wall : ReadingFit::fits;
    return false;
  });
  return fit;
}

BeamFits classify_beams(const grid::OccupancyGrid& map, const geometry::Pose2& robot,
                        const PreparedBeams& beams, const ReadingMargins& margins) {
  const geometry::Pose2 sensor = robot.compose(beams.sensor_pose);
  BeamFits fits;
  for (std::size_t b = 0; b < beams.size(); ++b) {
    if (beams.no_return[b] != 0) continue;
    ++fits.returned;
    switch (classify_reading(map, sensor, robot.yaw + beams.robot_angle[b], beams.ranges[b], margins)) {
      case ReadingFit::short_of_map: ++fits.short_of_map; break;
      case ReadingFit::through_wall: ++fits.through_wall; break;
      case ReadingFit::fits: break;
    }
  }
  return fits;
}

std::size_t mark_short_readings(const grid::OccupancyGrid& map, const geometry::Pose2& robot,
                                const LaserScan& scan, const ReadingMargins& margins,
                                std::size_t most_checked,
                                std::vector<unsigned char>& out) {
  const geometry::Pose2 sensor = robot.compose(scan.sensor_pose);
  const std::size_t readings = std::min(scan.ranges.size(), scan.bearings.size());
  out.assign(scan.ranges.size(), 1);
  std::size_t usable = 0;
  for (std::size_t i = 0; i < readings; ++i) usable += usable_reading(scan, i) ? 1 : 0;
  if (usable == 0 || most_checked == 0) return 0;
  const std::size_t checked = std::min(usable, most_checked);
  const double step =
      checked > 1 ? static_cast<double>(usable - 1) / static_cast<double>(checked - 1) : 0.0;
  std::size_t short_count = 0;
  std::size_t usable_index = 0;
  std::size_t next = 0;
  for (std::size_t i = 0; i < readings && next < checked; ++i) {
    if (!usable_reading(scan, i)) continue;
    const auto wanted = static_cast<std::size_t>(std::lround(static_cast<double>(next) * step));
    if (usable_index++ != wanted) continue;
    ++next;
    const double range = scan.ranges[i];
    const bool is_short = range < scan.max_range &&
                          classify_reading(map, sensor, sensor.yaw + scan.bearings[i], range,
                                           margins) == ReadingFit::short_of_map;
    out[i] = is_short ? 1 : 0;
    short_count += is_short ? 1 : 0;
  }
  return short_count;
}

}  // namespace playerkit::amcl
