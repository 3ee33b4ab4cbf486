#pragma once
// The robot's sonar ring: poses from the parameter row (p2os.md §4.3), and
// ranges ray-cast through the map from each transducer.

#include "algorithms/geometry/pose2.hpp"
#include "algorithms/grid/occupancy_grid.hpp"
#include "emulators/mobile_base/range_ring.hpp"
#include "families/p2os/protocol/robot_params.hpp"

#include <span>
#include <vector>

namespace playerkit::emulators::p2os {

class SonarArray {
 public:
  // The sheet's poses for the row, or — for rows the sheet gives none —
  // sonar_count transducers spread evenly around the robot at 80 % of its
  // radius, index 0 facing left and going clockwise as on a real ring.
  explicit SonarArray(const hardware::p2os::RobotParams& params);

  std::span<const hardware::p2os::SonarPose> poses() const { return poses_; }
  int size() const { return static_cast<int>(poses_.size()); }

  // Metres from transducer `index` to the first occupied cell along its
  // axis, or `max_range` (always, without a map).
  double range(int index, const grid::OccupancyGrid* map, const geometry::Pose2& robot,
               double max_range) const {
    return ring_.range(index, map, robot, max_range);
  }

  // The transducer's pose in the world, metres and radians.
  geometry::Pose2 world_pose(int index, const geometry::Pose2& robot) const { return ring_.world_pose(index, robot); }

 private:
  std::vector<hardware::p2os::SonarPose> poses_;  // as the row gives them: mm and whole degrees
  mobile_base::RangeRing ring_;                    // the same in metres and radians
};

}  // namespace playerkit::emulators::p2os
