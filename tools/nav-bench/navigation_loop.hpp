#pragma once
// The classic Player/Stage navigation loop — a simulated Pioneer with a
// laser, amcl localizing it, wavefront planning on the map and handing
// waypoints to vfh — run in simulated time, in one thread, with the same
// pure cores the amcl, wavefront and vfh drivers run (AmclFilter,
// WavefrontNavigator, VfhNavigator). No server and no threads: the same
// world, setup and seed give the same run, however loaded the machine is.
// Only the timing figures (processor milliseconds of planning and vfh) vary.
//
//   NavigationLoop loop(world_file, setup, seed);
//   for (const geometry::Pose2& goal : goals) outcomes.push_back(loop.drive_to(goal));

#include <filesystem>
#include <functional>
#include <memory>
#include <vector>

#include "algorithms/geometry/pose2.hpp"
#include "algorithms/grid/occupancy_grid.hpp"
#include "algorithms/wavefront/wavefront_planner.hpp"
#include "nav_report.hpp"
#include "navigation_setup.hpp"

namespace playerkit::nav_bench {

// One step of the loop, for a trace.
struct StepRecord {
  double time = 0.0;             // s, simulated
  geometry::Pose2 truth;
  geometry::Pose2 estimate;      // amcl's, map frame
  geometry::Pose2 odometry;      // the base's, odometric frame (vfh steers by it)
  double speed = 0.0;            // commanded, m/s
  double turn_rate = 0.0;        // commanded, rad/s
  geometry::Pose2 local_goal;    // the waypoint vfh drives to, odometric frame
  bool local_goal_active = false;
  bool stalled = false;
  const char* vfh_phase = "";    // what vfh did (vfh::phase_name)
};

class NavigationLoop {
 public:
  // Loads the world and finds its first robot that carries a laser. Throws
  // sim::worldfile::WorldFileError for a bad world and std::runtime_error
  // when no robot has a laser.
  NavigationLoop(const std::filesystem::path& world_file, const NavigationSetup& setup, std::uint64_t seed);
  ~NavigationLoop();
  NavigationLoop(const NavigationLoop&) = delete;
  NavigationLoop& operator=(const NavigationLoop&) = delete;

  // Sends `goal` (map frame) to the loop and runs until wavefront says it
  // is reached, refuses or gives it up, or the time limit passes.
  GoalOutcome drive_to(const geometry::Pose2& goal);

  [[nodiscard]] geometry::Pose2 true_pose() const;
  [[nodiscard]] const grid::OccupancyGrid& map() const;
  // A planner on the world's map with the setup's clearance: for choosing
  // goals and for the reference plans.
  [[nodiscard]] wavefront::WavefrontPlanner& reference_planner();

  // Called after every step (nav-bench --trace).
  void set_step_observer(std::function<void(const StepRecord&)> observer);

  // Every step's body clearance and every vfh cycle's time so far.
  [[nodiscard]] std::vector<double>& clearances();
  [[nodiscard]] std::vector<double>& vfh_milliseconds();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace playerkit::nav_bench
