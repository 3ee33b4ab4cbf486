#include "algorithms/wavefront/wavefront_planner.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace playerkit::wavefront {
namespace wavefront_planner_test {

using grid::CellState;
using grid::OccupancyGrid;

constexpr double kResolution = 0.1;

OccupancyGrid free_room(int width, int height) {
  return OccupancyGrid(width, height, kResolution, {0.0, 0.0}, CellState::free);
}

void fill(OccupancyGrid& grid, int col0, int row0, int col1, int row1, CellState state) {
  for (int row = row0; row <= row1; ++row) {
    for (int col = col0; col <= col1; ++col) {
      if (grid.contains(col, row)) grid.set(col, row, state);
    }
  }
}

// A free room with `blobs` rectangles of up to (largest + 1) cells a side at
// random, one in four unknown, the rest occupied.
OccupancyGrid cluttered_room(std::mt19937& random, int width, int height, int blobs, int largest) {
  OccupancyGrid grid = free_room(width, height);
  std::uniform_int_distribution<int> col(0, width - 1), row(0, height - 1), size(0, largest), kind(0, 3);
  for (int blob = 0; blob < blobs; ++blob) {
    // One draw per statement: the order of a call's arguments is unspecified
    // (GCC and clang differ), and the room must not depend on the compiler.
    const int c = col(random);
    const int r = row(random);
    const int c_end = c + size(random);
    const int r_end = r + size(random);
    const bool unknown = kind(random) == 0;
    fill(grid, c, r, c_end, r_end, unknown ? CellState::unknown : CellState::occupied);
  }
  return grid;
}

// Independent of the planner: distance from a point to every occupied or
// unknown square, by brute force (the map's edge is not counted here).
double distance_to_cells(const OccupancyGrid& grid, const Eigen::Vector2d& p) {
  double best = std::numeric_limits<double>::infinity();
  const double res = grid.resolution();
  for (int row = 0; row < grid.height(); ++row) {
    for (int col = 0; col < grid.width(); ++col) {
      if (grid.at(col, row) == CellState::free) continue;
      const Eigen::Vector2d lo = grid.origin() + Eigen::Vector2d(col, row) * res;
      const double dx = std::max({lo.x() - p.x(), 0.0, p.x() - lo.x() - res});
      const double dy = std::max({lo.y() - p.y(), 0.0, p.y() - lo.y() - res});
      best = std::min(best, std::hypot(dx, dy));
    }
  }
  return best;
}

// The closest any densely sampled point of the path comes to an obstacle:
// samples a tenth of a cell apart, each against every obstacle square.
double sampled_path_clearance(const OccupancyGrid& grid, const std::vector<Eigen::Vector2d>& path) {
  std::vector<Eigen::Vector2d> squares;  // lower-left corners
  const double res = grid.resolution();
  for (int row = 0; row < grid.height(); ++row) {
    for (int col = 0; col < grid.width(); ++col) {
      if (grid.at(col, row) != CellState::free) squares.push_back(grid.origin() + Eigen::Vector2d(col, row) * res);
    }
  }
  double best_squared = std::numeric_limits<double>::infinity();
  for (std::size_t i = 1; i < path.size(); ++i) {
    const Eigen::Vector2d a = path[i - 1], b = path[i];
    const int samples = std::max(1, static_cast<int>(std::ceil((b - a).norm() / (0.1 * res))));
    for (int k = 0; k <= samples; ++k) {
      const Eigen::Vector2d p = a + (b - a) * k / samples;
      for (const Eigen::Vector2d& lo : squares) {
        const double dx = std::max({lo.x() - p.x(), 0.0, p.x() - lo.x() - res});
        const double dy = std::max({lo.y() - p.y(), 0.0, p.y() - lo.y() - res});
        best_squared = std::min(best_squared, dx * dx + dy * dy);
      }
    }
  }
  return std::sqrt(best_squared);
}

PlannerParameters clearance_only(double radius, double safety) {
  PlannerParameters p;
  p.robot_radius = radius;
  p.safety_distance = safety;
  p.penalty_distance = 0.0;  // shortest paths, for known optima
  return p;
}

void expect_ends(const PlanResult& plan, const Eigen::Vector2d& start, const Eigen::Vector2d& goal) {
  ASSERT_TRUE(plan.found()) << static_cast<int>(plan.status);
  ASSERT_GE(plan.waypoints.size(), 2u);
  EXPECT_EQ(plan.waypoints.front(), start);
  EXPECT_EQ(plan.waypoints.back(), goal);
  double length = 0.0;
  for (std::size_t i = 1; i < plan.waypoints.size(); ++i) length += (plan.waypoints[i] - plan.waypoints[i - 1]).norm();
  EXPECT_NEAR(plan.length_m, length, 1e-9);
}

// The shortest path from s around a disc of radius r at c, the disc on its
// right (the path turns clockwise), to where it leaves at angle `leave`.
// Returns the length of the tangent plus the arc.
double tangent_and_arc(const Eigen::Vector2d& s, const Eigen::Vector2d& c, double r, double leave) {
  const Eigen::Vector2d v = s - c;
  const double touch = std::atan2(v.y(), v.x()) - std::acos(r / v.norm());
  double arc = touch - leave;
  while (arc < 0) arc += 2 * std::numbers::pi;
  while (arc >= 2 * std::numbers::pi) arc -= 2 * std::numbers::pi;
  return std::sqrt(v.squaredNorm() - r * r) + r * arc;
}

TEST(WavefrontPlanner, InSightTheGoalIsOneStraightSegment) {
  const OccupancyGrid room = free_room(60, 40);
  WavefrontPlanner planner(room);
  const Eigen::Vector2d start(0.73, 0.91), goal(5.12, 3.07);
  const PlanResult plan = planner.plan(start, goal);
  expect_ends(plan, start, goal);
  EXPECT_EQ(plan.waypoints.size(), 2u);
  EXPECT_NEAR(plan.length_m, (goal - start).norm(), 1e-12);
  EXPECT_EQ(plan.cells_settled, 0u);
}

// A wall from the bottom edge with a gap above: the shortest path with
// clearance R wraps the wall's two top corners on circles of radius R.
TEST(WavefrontPlanner, AroundAWallEndThePathIsShortestWithinOneCell) {
  OccupancyGrid grid = free_room(80, 60);
  fill(grid, 40, 0, 40, 39, CellState::occupied);  // x 4.0-4.1, y 0-4.0
  const PlannerParameters parameters = clearance_only(0.2, 0.1);
  const double r = parameters.required_clearance();
  WavefrontPlanner planner(grid, parameters);
  for (const auto& [start, goal] : {std::pair{Eigen::Vector2d(2.0, 1.0), Eigen::Vector2d(6.0, 1.5)},
                                    std::pair{Eigen::Vector2d(3.0, 0.5), Eigen::Vector2d(5.5, 3.0)}}) {
    const PlanResult plan = planner.plan(start, goal);
    expect_ends(plan, start, goal);
    const Eigen::Vector2d left(4.0, 4.0), right(4.1, 4.0);
    const Eigen::Vector2d mirrored_goal(2 * 4.05 - goal.x(), goal.y());
    const Eigen::Vector2d mirrored_right(2 * 4.05 - right.x(), right.y());
    // Mirror the second half so both halves turn clockwise onto the top.
    const double optimum = tangent_and_arc(start, left, r, std::numbers::pi / 2) + (right - left).norm() +
                           tangent_and_arc(mirrored_goal, mirrored_right, r, std::numbers::pi / 2);
    EXPECT_GE(plan.length_m, optimum - 1e-9);
    EXPECT_LE(plan.length_m, optimum + kResolution) << "optimum " << optimum;
    EXPECT_GE(sampled_path_clearance(grid, plan.waypoints), r - 1e-9);
  }
}

// A square pillar in a room: over its top, which is nearer the line.
TEST(WavefrontPlanner, AcrossAnOpenRoomWithAPillarThePathIsShortestWithinOneCell) {
  OccupancyGrid grid = free_room(100, 60);
  fill(grid, 45, 25, 54, 34, CellState::occupied);  // a 1 m pillar, x 4.5-5.5, y 2.5-3.5
  const PlannerParameters parameters = clearance_only(0.15, 0.15);
  const double r = parameters.required_clearance();
  WavefrontPlanner planner(grid, parameters);
  const Eigen::Vector2d start(1.0, 3.2), goal(9.0, 3.2);
  const PlanResult plan = planner.plan(start, goal);
  expect_ends(plan, start, goal);
  // Over the pillar's top: tangent to the circle around its top-left corner,
  // along its top, tangent down from its top-right corner.
  const Eigen::Vector2d top_left(4.5, 3.5), top_right(5.5, 3.5);
  const double optimum = 2 * tangent_and_arc(start, top_left, r, std::numbers::pi / 2) + (top_right - top_left).norm();
  EXPECT_GE(plan.length_m, optimum - 1e-9);
  EXPECT_LE(plan.length_m, optimum + kResolution) << "optimum " << optimum;
  EXPECT_GE(sampled_path_clearance(grid, plan.waypoints), r - 1e-9);
}

// A wall across the room with one door: 2 (radius + safety) wide passes,
// one cell narrower does not.
OccupancyGrid wall_with_door(int door_cells) {
  OccupancyGrid grid = free_room(60, 40);
  fill(grid, 0, 20, 59, 21, CellState::occupied);
  fill(grid, 25, 20, 25 + door_cells - 1, 21, CellState::free);
  return grid;
}

TEST(WavefrontPlanner, ADoorExactlyTwiceTheClearanceWideIsFound) {
  const PlannerParameters parameters = clearance_only(0.15, 0.1);  // 2 x 0.25 m = 5 cells
  const OccupancyGrid grid = wall_with_door(5);
  WavefrontPlanner planner(grid, parameters);
  const Eigen::Vector2d start(1.0, 1.0), goal(5.0, 3.5);
  const PlanResult plan = planner.plan(start, goal);
  expect_ends(plan, start, goal);
  EXPECT_NEAR(sampled_path_clearance(grid, plan.waypoints), 0.25, 1e-9);  // in the door's middle
  EXPECT_NEAR(plan.min_clearance_m, 0.25, 1e-9);
}

TEST(WavefrontPlanner, ANarrowerDoorIsNotFound) {
  const PlannerParameters parameters = clearance_only(0.15, 0.1);
  WavefrontPlanner planner(wall_with_door(4), parameters);
  const PlanResult plan = planner.plan({1.0, 1.0}, {5.0, 3.5});
  EXPECT_EQ(plan.status, PlanStatus::unreachable);
  EXPECT_TRUE(plan.waypoints.empty());
  EXPECT_GT(plan.cells_settled, 100u);
  EXPECT_NE(describe_failure(plan, parameters).find("0.25 m"), std::string::npos);
}

TEST(WavefrontPlanner, AnEnclosedGoalIsUnreachable) {
  OccupancyGrid grid = free_room(60, 60);
  fill(grid, 30, 30, 50, 50, CellState::occupied);
  fill(grid, 31, 31, 49, 49, CellState::free);  // a closed box, 1.8 m inside
  WavefrontPlanner planner(grid);
  const PlanResult plan = planner.plan({1.0, 1.0}, {4.0, 4.0});
  EXPECT_EQ(plan.status, PlanStatus::unreachable);
  // And out of it, the same.
  EXPECT_EQ(planner.plan({4.0, 4.0}, {1.0, 1.0}).status, PlanStatus::unreachable);
}

TEST(WavefrontPlanner, StartsAndGoalsThatCannotBeUsedSayWhy) {
  OccupancyGrid grid = free_room(60, 40);
  fill(grid, 10, 10, 12, 12, CellState::occupied);
  fill(grid, 40, 10, 42, 12, CellState::unknown);
  const PlannerParameters parameters;  // 0.30 m
  WavefrontPlanner planner(grid, parameters);
  const Eigen::Vector2d fine(3.0, 3.0);
  const auto start_state = [&](const Eigen::Vector2d& p) {
    const PlanResult plan = planner.plan(p, fine);
    EXPECT_EQ(plan.status, PlanStatus::start_invalid);
    return plan.start;
  };
  EXPECT_EQ(start_state({1.15, 1.15}), EndpointState::occupied);
  EXPECT_EQ(start_state({4.15, 1.15}), EndpointState::unknown);
  EXPECT_EQ(start_state({-0.5, 1.0}), EndpointState::outside_map);
  EXPECT_EQ(start_state({1.0, 9.0}), EndpointState::outside_map);
  EXPECT_EQ(start_state({0.1, 2.0}), EndpointState::too_close);  // 0.1 m from the map's edge
  const PlanResult near_unknown = planner.plan(fine, {4.5, 1.15});  // 0.2 m right of the unknown block
  EXPECT_EQ(near_unknown.status, PlanStatus::goal_invalid);
  EXPECT_EQ(near_unknown.goal, EndpointState::too_close);
  EXPECT_NEAR(near_unknown.goal_clearance_m, 0.2, 1e-9);
  EXPECT_EQ(describe_failure(near_unknown, parameters),
            "goal is 0.20 m from an occupied or unknown cell, closer than 0.30 m (robot radius + safety)");
}

// 1.5 let the path graze unknown cells (they blocked but did not inflate);
// here they are kept at the full clearance like walls.
TEST(WavefrontPlanner, UnknownCellsKeepTheClearanceToo) {
  OccupancyGrid grid = free_room(80, 40);
  fill(grid, 38, 0, 41, 29, CellState::unknown);  // an unknown strip from the bottom, y 0-3.0
  const PlannerParameters parameters = clearance_only(0.15, 0.15);
  WavefrontPlanner planner(grid, parameters);
  const PlanResult plan = planner.plan({2.0, 1.0}, {6.0, 1.0});
  ASSERT_TRUE(plan.found());
  const double clearance = sampled_path_clearance(grid, plan.waypoints);
  EXPECT_GE(clearance, 0.3 - 1e-9);
  EXPECT_LT(clearance, 0.3 + kResolution);  // it does go round closely
  double highest = 0;
  for (const auto& p : plan.waypoints) highest = std::max(highest, p.y());
  EXPECT_GE(highest, 3.3 - 1e-9);
}

// Random clutter: every plan found keeps the clearance, checked by brute
// force on densely sampled segments; the 0.45 m penalty band is on.
TEST(WavefrontPlanner, EveryPathKeepsTheClearanceOnClutteredMaps) {
  std::mt19937 random(5);
  int found = 0, refused = 0;
  for (int map = 0; map < 4; ++map) {
    const OccupancyGrid grid = cluttered_room(random, 70, 50, 25, 4);
    PlannerParameters parameters;
    parameters.robot_radius = 0.12 + 0.04 * map;
    parameters.safety_distance = 0.05;
    WavefrontPlanner planner(grid, parameters);
    std::uniform_real_distribution<double> x(0.0, 7.0), y(0.0, 5.0);
    for (int trial = 0; trial < 12; ++trial) {
      const Eigen::Vector2d start{x(random), y(random)}, goal{x(random), y(random)};
      const PlanResult plan = planner.plan(start, goal);
      if (!plan.found()) {
        ++refused;
        continue;
      }
      ++found;
      expect_ends(plan, start, goal);
      const double required = parameters.required_clearance();
      EXPECT_GE(sampled_path_clearance(grid, plan.waypoints), required - 1e-9);
      EXPECT_GE(plan.min_clearance_m, required - 1e-9);
    }
  }
  EXPECT_GT(found, 10);  // the check ran on real paths
  EXPECT_GT(refused, 0);
}

// The bound on the rest of the way only steers the wavefront: what it finds
// costs what the even wavefront finds, on cluttered maps with penalties.
TEST(WavefrontPlanner, SteeringTowardTheStartKeepsTheLeastCost) {
  std::mt19937 random(11);
  int compared = 0, fewer = 0;
  for (int map = 0; map < 4; ++map) {
    const OccupancyGrid grid = cluttered_room(random, 90, 70, 45, 6);
    PlannerParameters parameters;
    parameters.robot_radius = 0.1 + 0.03 * map;
    parameters.safety_distance = 0.05;
    parameters.distance_penalty = 0.5 * map;
    WavefrontPlanner steered(grid, parameters), even(grid, parameters);
    even.use_goal_direction(false);
    std::uniform_real_distribution<double> x(0.0, 9.0), y(0.0, 7.0);
    for (int trial = 0; trial < 15; ++trial) {
      const Eigen::Vector2d start{x(random), y(random)}, goal{x(random), y(random)};
      const PlanResult a = steered.plan(start, goal), b = even.plan(start, goal);
      ASSERT_EQ(a.status, b.status) << "map " << map << " trial " << trial;
      if (!a.found() || b.cells_settled == 0) continue;
      ++compared;
      EXPECT_NEAR(a.cost, b.cost, 1e-4 * b.cost) << "map " << map << " trial " << trial;
      EXPECT_LE(a.cells_settled, b.cells_settled);
      fewer += a.cells_settled < b.cells_settled ? 1 : 0;
      expect_ends(a, start, goal);
      EXPECT_GE(a.min_clearance_m, parameters.required_clearance() - 1e-9);
    }
  }
  EXPECT_GT(compared, 20);
  EXPECT_GT(fewer, compared / 2);
}

TEST(WavefrontPlanner, ANewGoalOnTheSameMapGivesWhatAFreshPlannerGives) {
  OccupancyGrid grid = free_room(80, 60);
  fill(grid, 20, 0, 22, 44, CellState::occupied);
  fill(grid, 50, 15, 52, 59, CellState::occupied);
  WavefrontPlanner reused(grid);
  const Eigen::Vector2d start(1.0, 1.0);
  const PlanResult first = reused.plan(start, {7.5, 5.5});
  ASSERT_TRUE(first.found());
  for (const Eigen::Vector2d& goal : {Eigen::Vector2d(4.0, 1.0), Eigen::Vector2d(7.5, 0.6)}) {
    const PlanResult again = reused.plan(start, goal);
    WavefrontPlanner fresh(grid);
    const PlanResult expected = fresh.plan(start, goal);
    ASSERT_TRUE(expected.found());
    EXPECT_EQ(again.waypoints, expected.waypoints);
    EXPECT_EQ(again.cells_settled, expected.cells_settled);
    EXPECT_GE(again.waypoints.size(), 3u);  // not in sight: the wavefront ran
  }
}

// A wall with a narrow gap on the straight line and a wide one off to the
// side: without a penalty the path squeezes through the narrow gap; with a
// strong one it takes the detour, where it can keep well off the walls.
TEST(WavefrontPlanner, ThePenaltyBandPrefersRoomierRoutes) {
  OccupancyGrid grid = free_room(100, 60);
  fill(grid, 0, 29, 99, 30, CellState::occupied);
  fill(grid, 48, 29, 54, 30, CellState::free);  // 0.7 m: passes 2 x 0.3 m
  fill(grid, 75, 29, 94, 30, CellState::free);  // 2 m
  PlannerParameters shortest = clearance_only(0.15, 0.15);
  PlannerParameters roomy = shortest;
  roomy.penalty_distance = 0.5;
  roomy.distance_penalty = 10.0;
  const Eigen::Vector2d start(5.0, 1.0), goal(5.0, 5.0);
  WavefrontPlanner a(grid, shortest), b(grid, roomy);
  const PlanResult narrow = a.plan(start, goal), wide = b.plan(start, goal);
  ASSERT_TRUE(narrow.found());
  ASSERT_TRUE(wide.found());
  const auto rightmost = [](const PlanResult& plan) {
    double x = 0;
    for (const auto& p : plan.waypoints) x = std::max(x, p.x());
    return x;
  };
  EXPECT_LT(rightmost(narrow), 5.5);
  EXPECT_GT(rightmost(wide), 7.5);
  EXPECT_LT(narrow.length_m, wide.length_m);
  EXPECT_GE(sampled_path_clearance(grid, narrow.waypoints), 0.3 - 1e-9);
  EXPECT_GE(sampled_path_clearance(grid, wide.waypoints), 0.3 - 1e-9);
}

TEST(WavefrontPlanner, ParametersAreChecked) {
  const OccupancyGrid room = free_room(10, 10);
  PlannerParameters p;
  p.robot_radius = 0.0;
  EXPECT_THROW(WavefrontPlanner(room, p), std::invalid_argument);
  p = {};
  p.safety_distance = -0.1;
  EXPECT_THROW(validate(p), std::invalid_argument);
  p = {};
  p.distance_penalty = std::nan("");
  EXPECT_THROW(validate(p), std::invalid_argument);
}

}  // namespace wavefront_planner_test
}  // namespace playerkit::wavefront
