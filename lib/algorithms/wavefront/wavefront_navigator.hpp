#pragma once
// What the wavefront driver decides each cycle (wavefront.md §2), as pure
// logic: a goal on the map is planned from the localized pose, its
// waypoints handed to the local planner one at a time in the odometric
// frame, and it is planned again when the robot strays from the path, the
// localization jumps or the local planner says it is stuck — at most
// `most_plans_per_goal` times, then given up. A goal that cannot be planned
// is refused at once. A waypoint is handed down again when the localization
// has since moved it in the odometric frame, so the local planner, which
// steers by odometry, stops where the map says. The driver adds the wire; `nav-bench` runs the same
// decisions in simulated time.
//
//   WavefrontNavigator navigator(map, planner_parameters, settings);
//   navigator.set_goal({6.0, 3.0, 0.0});
//   const BaseOrder order = navigator.cycle(odometry, localized_pose, vfh_stalled);
//   if (order.kind == BaseOrder::Kind::drive_to) send(order.target);  // odometric frame
//   for (const NavigationEvent& event : navigator.take_events()) log(event.message);

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "algorithms/geometry/pose2.hpp"
#include "algorithms/grid/occupancy_grid.hpp"
#include "algorithms/wavefront/wavefront_planner.hpp"
#include "algorithms/wavefront/waypoint_follower.hpp"

namespace playerkit::wavefront {

struct NavigatorSettings {
  FollowerSettings follower;
  double jump_distance = 0.5;   // m between two localized poses: a jump, plan again
  int most_plans_per_goal = 10;  // the robot keeps straying or getting stuck: give up
};

// What the local planner is told this cycle.
struct BaseOrder {
  enum class Kind { none, drive_to, stop };
  Kind kind = Kind::none;
  geometry::Pose2 target;  // drive_to: in the odometric frame
};

struct NavigationEvent {
  enum class Kind { reached, refused, replanning, given_up };
  Kind kind = Kind::reached;
  std::string message;  // a log line without the device's name: "goal (6.00, 3.00) refused: ..."
};

class WavefrontNavigator {
 public:
  // Throws what WavefrontPlanner throws for bad parameters.
  WavefrontNavigator(const grid::OccupancyGrid& map, const PlannerParameters& planner,
                     const NavigatorSettings& settings);

  // A goal on the map. The command buffer is persistent: the same goal
  // again (within a millimetre and a milliradian) is not a new one and
  // returns false. Planned at the next cycle, from the pose then.
  bool set_goal(const geometry::Pose2& goal);

  // One cycle on fresh odometry: the odometric pose, the localized pose on
  // the map, and whether the local planner reports a stall.
  BaseOrder cycle(const geometry::Pose2& odometry, const geometry::Pose2& map_pose, bool local_planner_stalled);

  // Forgets the goal and the plan (the driver's open()).
  void reset();

  // Whether the local planner is being driven: stall is the negation.
  [[nodiscard]] bool driving() const { return driving_; }
  [[nodiscard]] std::vector<NavigationEvent> take_events();
  [[nodiscard]] const WaypointFollower& follower() const { return follower_; }
  [[nodiscard]] const WavefrontPlanner& planner() const { return planner_; }

  [[nodiscard]] std::uint64_t goals_reached() const { return reached_; }
  [[nodiscard]] std::uint64_t goals_refused() const { return refused_; }
  [[nodiscard]] std::uint64_t plans() const { return plans_; }
  [[nodiscard]] std::uint64_t replans() const { return replans_; }

 private:
  void plan(const geometry::Pose2& from, const geometry::Pose2& goal, BaseOrder& order);
  void replan(const geometry::Pose2& from, const std::string& why, BaseOrder& order);
  void follow(const geometry::Pose2& map_pose, BaseOrder& order);
  void give_up(BaseOrder& order);
  void say(NavigationEvent::Kind kind, std::string message);

  NavigatorSettings settings_;
  WavefrontPlanner planner_;
  WaypointFollower follower_;
  std::optional<geometry::Pose2> goal_;          // the last goal given
  std::optional<geometry::Pose2> pending_goal_;  // given, not planned yet
  std::optional<geometry::Pose2> last_map_pose_;
  geometry::Pose2 to_odometry_;  // odometric = this ∘ map
  geometry::Pose2 sent_;         // the waypoint last handed down, odometric frame
  int plans_for_goal_ = 0;
  bool driving_ = false;
  std::vector<NavigationEvent> events_;
  std::uint64_t reached_ = 0;
  std::uint64_t refused_ = 0;
  std::uint64_t plans_ = 0;
  std::uint64_t replans_ = 0;
};

}  // namespace playerkit::wavefront
