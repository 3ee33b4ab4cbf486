#include "emulators/mobile_base/range_ring.hpp"

#include <cmath>
#include <numbers>

#include "algorithms/grid/ray_cast.hpp"

namespace playerkit::emulators::mobile_base {

geometry::Pose2 RangeRing::world_pose(int index, const geometry::Pose2& robot) const {
  return robot.compose(poses_.at(static_cast<std::size_t>(index)));
}

double RangeRing::range(int index, const grid::OccupancyGrid* map, const geometry::Pose2& robot,
                        double max_range) const {
  if (map == nullptr) return max_range;
  const geometry::Pose2 sensor = world_pose(index, robot);
  return grid::cast_ray(*map, sensor.translation(), sensor.yaw, max_range, grid::RayStop::occupied);
}

std::vector<geometry::Pose2> evenly_spaced_ring(int count, double radius, double first_heading, RingOrder order) {
  std::vector<geometry::Pose2> poses;
  if (count <= 0) return poses;
  const double step = (order == RingOrder::clockwise ? -2.0 : 2.0) * std::numbers::pi / count;
  for (int i = 0; i < count; ++i) {
    const double heading = geometry::normalize_angle(first_heading + step * i);
    poses.push_back({radius * std::cos(heading), radius * std::sin(heading), heading});
  }
  return poses;
}

}  // namespace playerkit::emulators::mobile_base
