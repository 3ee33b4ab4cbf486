#pragma once
// A robot's ring of range sensors (sonar, ir): each transducer's pose on the
// robot, and the range it reads, ray-cast through the map along its axis.

#include <vector>

#include "algorithms/geometry/pose2.hpp"
#include "algorithms/grid/occupancy_grid.hpp"

namespace playerkit::emulators::mobile_base {

class RangeRing {
 public:
  RangeRing() = default;
  // Poses in the robot's frame: metres and radians, yaw along the axis.
  explicit RangeRing(std::vector<geometry::Pose2> transducer_poses) : poses_(std::move(transducer_poses)) {}

  [[nodiscard]] int size() const { return static_cast<int>(poses_.size()); }
  [[nodiscard]] const std::vector<geometry::Pose2>& poses() const { return poses_; }

  // Metres from transducer `index` to the first occupied cell along its
  // axis, or `max_range` (always, without a map).
  [[nodiscard]] double range(int index, const grid::OccupancyGrid* map, const geometry::Pose2& robot,
                             double max_range) const;

  // The transducer's pose in the world.
  [[nodiscard]] geometry::Pose2 world_pose(int index, const geometry::Pose2& robot) const;

 private:
  std::vector<geometry::Pose2> poses_;
};

// `count` transducers spread evenly around a round robot at `radius`, index
// 0 facing `first_heading` and the rest following clockwise (as a Pioneer's
// ring) or counter-clockwise.
enum class RingOrder { clockwise, counter_clockwise };
[[nodiscard]] std::vector<geometry::Pose2> evenly_spaced_ring(int count, double radius, double first_heading,
                                                              RingOrder order);

}  // namespace playerkit::emulators::mobile_base
