#include "plan_command.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "localization/map_from_log.hpp"
#include "localization/trajectory.hpp"

namespace playerkit::amcl_offline {
namespace plan_command_test {

namespace fs = std::filesystem;
using grid::CellState;

// Brute force, independent of the planner: the distance from p to every
// occupied or unknown cell within `window` metres of it (cells farther
// away cannot be nearer than the window).
double distance_to_cells(const grid::OccupancyGrid& grid, const Eigen::Vector2d& p, double window) {
  const double res = grid.resolution();
  const Eigen::Vector2i centre = grid.world_to_cell(p);
  const int reach = static_cast<int>(std::ceil(window / res)) + 1;
  double best = window;
  for (int row = centre.y() - reach; row <= centre.y() + reach; ++row) {
    for (int col = centre.x() - reach; col <= centre.x() + reach; ++col) {
      if (grid.contains(col, row) && grid.at(col, row) == CellState::free) continue;
      const Eigen::Vector2d lo = grid.origin() + Eigen::Vector2d(col, row) * res;
      const double dx = std::max({lo.x() - p.x(), 0.0, p.x() - lo.x() - res});
      const double dy = std::max({lo.y() - p.y(), 0.0, p.y() - lo.y() - res});
      best = std::min(best, std::hypot(dx, dy));
    }
  }
  return best;
}

double sampled_clearance(const grid::OccupancyGrid& grid, const std::vector<Eigen::Vector2d>& path, double window) {
  double best = window;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const Eigen::Vector2d a = path[i - 1], b = path[i];
    const int samples = std::max(1, static_cast<int>(std::ceil((b - a).norm() / (0.1 * grid.resolution()))));
    for (int k = 0; k <= samples; ++k) best = std::min(best, distance_to_cells(grid, a + (b - a) * k / samples, window));
  }
  return best;
}

// The Intel Research Lab (Radish): its map made from the bundled corrected
// log, as `amcl-offline map` makes it; start and goal are poses the robot
// really had, far apart.
TEST(PlanOnARadishMap, AcrossTheIntelLabThePathKeepsItsClearance) {
  const fs::path log = fs::path(PLAYERKIT_TEST_DATA_DIR) / "radish" / "intel-corrected.log.gz";
  const grid::OccupancyGrid grid = localization::map_from_log(log, {.resolution = 0.05}).grid;
  const localization::Trajectory truth = localization::truth_from_log(log);
  ASSERT_GT(truth.size(), 100u);

  wavefront::PlannerParameters parameters;  // 0.15 + 0.15 m
  wavefront::WavefrontPlanner planner(grid, parameters);
  // The farthest pair among poses with room around them.
  std::vector<Eigen::Vector2d> roomy;
  for (std::size_t i = 0; i < truth.size(); i += 10) {
    const Eigen::Vector2d p = truth[i].pose.translation();
    if (planner.clearance().point_clearance(p, 0.5) >= 0.5) roomy.push_back(p);
  }
  ASSERT_GT(roomy.size(), 10u);
  Eigen::Vector2d start = roomy.front(), goal = roomy.front();
  for (const auto& a : roomy) {
    for (const auto& b : roomy) {
      if ((a - b).norm() > (start - goal).norm()) std::tie(start, goal) = std::pair{a, b};
    }
  }
  ASSERT_GT((goal - start).norm(), 20.0);

  const wavefront::PlanResult plan = planner.plan(start, goal);
  ASSERT_TRUE(plan.found()) << wavefront::describe_failure(plan, parameters);
  EXPECT_EQ(plan.waypoints.front(), start);
  EXPECT_EQ(plan.waypoints.back(), goal);
  EXPECT_GE(plan.length_m, (goal - start).norm());
  EXPECT_GT(plan.waypoints.size(), 3u);  // the lab's corridors do not allow a straight line
  EXPECT_GE(sampled_clearance(grid, plan.waypoints, 0.5), parameters.required_clearance() - 1e-9);
}

TEST(PlanCommand, WritesTheWaypointsAsCsvFromStartToGoal) {
  PlanOptions options;
  options.map = (fs::path(PLAYERKIT_TEST_DATA_DIR) / "maps" / "stage-cave.png").string();
  options.map_loading.resolution = 0.032;
  options.start = Eigen::Vector2d(-6.0, -6.0);
  options.goal = Eigen::Vector2d(6.0, 6.0);
  std::ostringstream out, err;
  ASSERT_EQ(run_plan(options, out, err), kExitOk);
  std::istringstream rows(out.str());
  std::string line, first, last;
  std::getline(rows, line);
  EXPECT_EQ(line, "x,y");
  int count = 0;
  while (std::getline(rows, line)) {
    if (count++ == 0) first = line;
    last = line;
  }
  EXPECT_GE(count, 3);
  EXPECT_EQ(first, "-6.0000,-6.0000");
  EXPECT_EQ(last, "6.0000,6.0000");
  EXPECT_NE(err.str().find("waypoints"), std::string::npos);

  options.goal = Eigen::Vector2d(60.0, 6.0);
  try {
    run_plan(options, out, err);
    ADD_FAILURE() << "planned to a goal outside the map";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "no path from (-6.00, -6.00) to (60.00, 6.00): goal is outside the map");
  }
}

TEST(PlanCommand, TheStartOfATrackIsItsLastEstimateAtOrBeforeTheTime) {
  // Members set by name: TimedPose may gain fields (the estimate's spread).
  const auto at = [](double time, double x, double y) {
    localization::TimedPose pose;
    pose.time = time;
    pose.pose = {x, y, 0.0};
    return pose;
  };
  const localization::Trajectory track{at(10.0, 1.0, 2.0), at(11.0, 3.0, 4.0), at(12.0, 5.0, 6.0)};
  EXPECT_EQ(position_at(track, 11.0, "t.csv"), Eigen::Vector2d(3.0, 4.0));
  EXPECT_EQ(position_at(track, 11.9, "t.csv"), Eigen::Vector2d(3.0, 4.0));
  EXPECT_EQ(position_at(track, 99.0, "t.csv"), Eigen::Vector2d(5.0, 6.0));
  try {
    position_at(track, 9.5, "t.csv");
    ADD_FAILURE();
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "t.csv: no estimate at or before 9.5 s (the first is at 10.000 s)");
  }
}

}  // namespace plan_command_test
}  // namespace playerkit::amcl_offline
