#include "algorithms/grid/square_caster.hpp"

#include "algorithms/grid/ray_cast.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <random>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace playerkit::grid {
namespace square_caster_test {

constexpr RayStop kBothStops[] = {RayStop::occupied, RayStop::occupied_or_unknown};

struct Ray {
  Eigen::Vector2d origin;
  double angle;
  double max_range;
};

// cast_ray is the specification; a floating-point difference is all that is
// allowed (random rays pass nowhere near rounding's distance of a corner).
double allowed_error(double max_range) { return 1e-9 * std::max(1.0, max_range); }

// Compares every ray in both stop modes, through both overloads and in one
// batch by each walker (the vector one only where the processor has it);
// returns how many answers were hits (neither max_range nor 0), so that
// callers can check the rays exercised what they meant to.
int expect_same_as_cast_ray(const OccupancyGrid& grid, const std::vector<Ray>& rays, const std::string& what) {
  int hits = 0;
  std::vector<SquareCaster::Ray> batch;
  for (const Ray& ray : rays) {
    batch.push_back({ray.origin, Eigen::Vector2d(std::cos(ray.angle), std::sin(ray.angle)), ray.max_range});
  }
  for (const RayStop stop : kBothStops) {
    const SquareCaster caster(grid, stop);
    std::vector<double> batch_ranges(batch.size()), scalar_ranges(batch.size());
    caster.ranges(batch, batch_ranges);
    caster.ranges(batch, scalar_ranges, SquareCaster::Walker::scalar);
    int failures = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
      const Ray& ray = rays[i];
      const double expected = cast_ray(grid, ray.origin, ray.angle, ray.max_range, stop);
      const double by_angle = caster.range(ray.origin, ray.angle, ray.max_range);
      const double by_direction = caster.range(ray.origin, batch[i].direction, ray.max_range);
      const bool wrong = std::abs(by_angle - expected) > allowed_error(ray.max_range) || by_direction != by_angle ||
                         batch_ranges[i] != by_angle || scalar_ranges[i] != by_angle;
      if (wrong && failures++ < 5) {
        ADD_FAILURE() << what << (stop == RayStop::occupied ? " (occupied)" : " (not free)") << ": origin ("
                      << ray.origin.x() << ", " << ray.origin.y() << ") angle " << ray.angle << " max_range "
                      << ray.max_range << ": cast_ray " << expected << ", caster " << by_angle << " / "
                      << by_direction << " / batch " << batch_ranges[i] << " / scalar batch " << scalar_ranges[i];
      }
      hits += expected > 0.0 && expected < ray.max_range;
    }
    EXPECT_EQ(failures, 0) << what << ": rays differing from cast_ray";
  }
  return hits;
}

void fill(OccupancyGrid& grid, int col0, int row0, int col1, int row1, CellState state) {
  for (int row = row0; row < row1; ++row) {
    for (int col = col0; col < col1; ++col) grid.set(col, row, state);
  }
}

// 6 m x 4.5 m at 5 cm: an unknown margin, outer walls, two rooms and a
// corridor joined by doorways, a pillar, a thin diagonal wall (corner to
// corner) and a patch of unknown floor.
OccupancyGrid rooms() {
  OccupancyGrid grid(123, 90, 0.05, {-2.0, -1.0}, CellState::unknown);
  fill(grid, 4, 4, 116, 86, CellState::occupied);
  fill(grid, 6, 6, 114, 84, CellState::free);
  fill(grid, 60, 6, 62, 84, CellState::occupied);   // dividing wall, 2 cells thick
  fill(grid, 60, 30, 62, 40, CellState::free);      // doorway
  fill(grid, 6, 50, 60, 51, CellState::occupied);   // thin wall in the left room
  fill(grid, 20, 50, 28, 51, CellState::free);      // doorway
  fill(grid, 85, 60, 91, 66, CellState::occupied);  // pillar
  fill(grid, 80, 15, 100, 30, CellState::unknown);  // unexplored floor
  fill(grid, 114, 40, 116, 44, CellState::free);    // a gap out to the unknown margin
  for (int k = 0; k < 20; ++k) grid.set(10 + k, 60 + k, CellState::occupied);  // diagonal, corner to corner
  return grid;
}

OccupancyGrid clutter(unsigned seed, int width, int height) {
  std::mt19937 random(seed);
  std::discrete_distribution<int> state({0.95, 0.02, 0.03});  // free, unknown, occupied
  OccupancyGrid grid(width, height, 0.1, {3.0, -7.0});
  for (int row = 0; row < grid.height(); ++row) {
    for (int col = 0; col < grid.width(); ++col) {
      grid.set(col, row, std::array{CellState::free, CellState::unknown, CellState::occupied}[static_cast<std::size_t>(
                             state(random))]);
    }
  }
  return grid;
}

// Rays from anywhere in (and a little around) the grid, every direction.
std::vector<Ray> random_rays(const OccupancyGrid& grid, unsigned seed, int count, double longest) {
  std::mt19937 random(seed);
  const Eigen::Vector2d size(grid.width() * grid.resolution(), grid.height() * grid.resolution());
  std::uniform_real_distribution<double> x(grid.origin().x() - 0.05 * size.x(), grid.origin().x() + 1.05 * size.x());
  std::uniform_real_distribution<double> y(grid.origin().y() - 0.05 * size.y(), grid.origin().y() + 1.05 * size.y());
  std::uniform_real_distribution<double> angle(-std::numbers::pi, std::numbers::pi);
  std::uniform_real_distribution<double> range(0.01, longest);
  std::vector<Ray> rays;
  for (int i = 0; i < count; ++i) rays.push_back({{x(random), y(random)}, angle(random), range(random)});
  return rays;
}

TEST(SquareCaster, AgreesWithCastRayInRooms) {
  const OccupancyGrid grid = rooms();
  const int hits = expect_same_as_cast_ray(grid, random_rays(grid, 1, 20000, 8.0), "rooms");
  EXPECT_GT(hits, 20000);  // of 40000 (both modes)
}

TEST(SquareCaster, AgreesWithCastRayInClutterOfOddSizes) {
  for (const auto& [width, height] : {std::pair{150, 110}, std::pair{7, 9}, std::pair{1, 40}, std::pair{64, 1}}) {
    const OccupancyGrid grid = clutter(static_cast<unsigned>(width), width, height);
    const int hits = expect_same_as_cast_ray(grid, random_rays(grid, 2, 5000, 20.0),
                                             "clutter " + std::to_string(width) + " x " + std::to_string(height));
    EXPECT_GT(hits, 200);  // of 10000: few rays stay long in the thin ones
  }
}

// Long stretches of open space: clear squares up to the 255-cell cap.
TEST(SquareCaster, AgreesWithCastRayInWideOpenSpace) {
  OccupancyGrid grid(2600, 2200, 0.05, {-60.0, -50.0}, CellState::free);
  std::mt19937 random(5);
  std::uniform_int_distribution<int> col(0, grid.width() - 1), row(0, grid.height() - 1);
  for (int i = 0; i < 40; ++i) {
    // One draw per statement: a call's arguments go in an unspecified order.
    const int c = col(random);
    grid.set(c, row(random), CellState::occupied);
  }
  fill(grid, 1000, 1000, 1003, 1400, CellState::occupied);
  const int hits = expect_same_as_cast_ray(grid, random_rays(grid, 3, 4000, 200.0), "open space");
  EXPECT_GT(hits, 100);
  // A map with no stopping cell at all.
  const OccupancyGrid empty(300, 200, 0.05, {0.0, 0.0}, CellState::free);
  EXPECT_EQ(expect_same_as_cast_ray(empty, random_rays(empty, 4, 2000, 30.0), "no walls"), 0);
}

TEST(SquareCaster, WallAtAKnownDistance) {
  OccupancyGrid grid(100, 50, 0.1, {-5.0, 0.0}, CellState::free);
  fill(grid, 80, 0, 81, 50, CellState::occupied);  // x in [3.0, 3.1]
  const SquareCaster caster(grid, RayStop::occupied);
  EXPECT_NEAR(caster.range({0.0, 2.5}, 0.0, 10.0), 3.0, 1e-12);
  EXPECT_NEAR(caster.range({-4.95, 2.5}, 0.0, 10.0), 7.95, 1e-12);
  // At 60 degrees the wall is 3 / cos(60) = 6 m away along the ray, past the grid's top (y = 5).
  EXPECT_EQ(caster.range({0.0, 0.1}, std::numbers::pi / 3, 10.0), 10.0);
  EXPECT_NEAR(caster.range({0.0, 0.1}, std::numbers::pi / 9, 10.0), 3.0 / std::cos(std::numbers::pi / 9), 1e-12);
  EXPECT_EQ(caster.range({0.0, 2.5}, 0.0, 2.9), 2.9);                 // short of the wall
  EXPECT_EQ(caster.range({0.0, 2.5}, std::numbers::pi, 10.0), 10.0);  // leaves the grid
  // Straight along a cell border (y = 2.5 is one): the row above it, as cast_ray.
  EXPECT_NEAR(caster.range({0.0, 2.5}, 0.0, 10.0), cast_ray(grid, {0.0, 2.5}, 0.0, 10.0, RayStop::occupied), 1e-12);
}

// A diagonal through cell corners, with the cells beside each corner free:
// no rounding can decide anything, and the wall cell on the diagonal stops it.
TEST(SquareCaster, DiagonalThroughCornersMeetsTheCellOnIt) {
  OccupancyGrid grid(40, 40, 1.0, {0.0, 0.0}, CellState::free);
  grid.set(30, 30, CellState::occupied);
  const SquareCaster caster(grid, RayStop::occupied);
  const double expected = std::hypot(29.5, 29.5);  // from (0.5, 0.5) to the corner (30, 30)
  EXPECT_NEAR(caster.range({0.5, 0.5}, std::numbers::pi / 4, 100.0), expected, 1e-9);
  EXPECT_NEAR(cast_ray(grid, {0.5, 0.5}, std::numbers::pi / 4, 100.0, RayStop::occupied), expected, 1e-9);
}

// The same going down and left, next to walls: at each corner the floor of
// the crossing gives the cell beside the corner, which the ray leaves at
// once. The walk bounced between the two cells beside a corner for ever
// before it let crossing times decide (found by a test of rays from cell corners).
TEST(SquareCaster, DiagonalThroughCornersGoingDownLeftEnds) {
  OccupancyGrid grid(40, 40, 1.0, {0.0, 0.0}, CellState::free);
  grid.set(5, 35, CellState::occupied);
  grid.set(4, 36, CellState::occupied);  // clearance 1 beside the corners passed
  grid.set(8, 39, CellState::occupied);
  const double angle = 5 * std::numbers::pi / 4;
  const Eigen::Vector2d origin(8.0, 38.0);  // a corner, and two more before the wall's
  const double expected = std::hypot(2.0, 2.0);
  const SquareCaster caster(grid, RayStop::occupied);
  EXPECT_NEAR(caster.range(origin, angle, 100.0), expected, 1e-9);
  const std::vector<SquareCaster::Ray> rays(5, {origin, {std::cos(angle), std::sin(angle)}, 100.0});
  std::vector<double> ranges(rays.size());
  caster.ranges(rays, ranges);
  for (const double range : ranges) EXPECT_NEAR(range, expected, 1e-9);
  EXPECT_NEAR(cast_ray(grid, origin, angle, 100.0, RayStop::occupied), expected, 1e-9);
}

// Rays from every third cell corner and centre of a cluttered grid of
// whole-metre cells, at every multiple of 45 degrees: they run along cell
// borders and through corners exactly, the cases rounding cannot decide.
// Every walk ends (the test hanging is its failure), alone as in a batch,
// at a stopping cell.
TEST(SquareCaster, RaysAlongBordersAndThroughCornersAllEnd) {
  const OccupancyGrid cluttered = clutter(21, 40, 40);  // its cells on a grid of whole metres at (0, 0)
  OccupancyGrid grid(40, 40, 1.0, {0.0, 0.0}, CellState::free);
  for (int row = 0; row < 40; ++row) {
    for (int col = 0; col < 40; ++col) grid.set(col, row, cluttered.at(col, row));
  }
  std::vector<SquareCaster::Ray> rays;
  for (int col = 0; col < 40; col += 3) {
    for (int row = 0; row < 40; row += 3) {
      for (int eighth = 0; eighth < 8; ++eighth) {
        const double angle = eighth * std::numbers::pi / 4;
        const Eigen::Vector2d direction(std::cos(angle), std::sin(angle));
        rays.push_back({{col, row}, direction, 60.0});
        rays.push_back({{col + 0.5, row + 0.5}, direction, 60.0});
      }
    }
  }
  for (const RayStop stop : kBothStops) {
    const SquareCaster caster(grid, stop);
    std::vector<double> batch(rays.size()), scalar_batch(rays.size());
    caster.ranges(rays, batch);
    caster.ranges(rays, scalar_batch, SquareCaster::Walker::scalar);
    for (std::size_t i = 0; i < rays.size(); ++i) {
      const double alone = caster.range(rays[i].origin, rays[i].direction, rays[i].max_range);
      EXPECT_EQ(alone, batch[i]) << "ray " << i;
      EXPECT_EQ(alone, scalar_batch[i]) << "ray " << i;
      // Where it stops, a stopping cell touches the ray: at a corner the
      // walk may pass on the other side of it from cast_ray's, so the cell
      // may not be cast_ray's.
      if (alone >= rays[i].max_range) continue;
      const Eigen::Vector2d stopped = rays[i].origin + alone * rays[i].direction;
      bool touches = false;
      for (const double dx : {-1e-9, 1e-9}) {
        for (const double dy : {-1e-9, 1e-9}) {
          const Eigen::Vector2i cell = grid.world_to_cell(stopped + Eigen::Vector2d(dx, dy));
          touches = touches || (grid.contains(cell.x(), cell.y()) &&
                                (stop == RayStop::occupied ? grid.at(cell.x(), cell.y()) == CellState::occupied
                                                           : grid.at(cell.x(), cell.y()) != CellState::free));
        }
      }
      EXPECT_TRUE(touches) << "ray " << i << " from (" << rays[i].origin.transpose() << ") along ("
                           << rays[i].direction.transpose() << ") stopped at (" << stopped.transpose() << ")";
    }
  }
}

TEST(SquareCaster, OriginInsideAStoppingCellGivesZero) {
  OccupancyGrid grid(20, 20, 0.5, {0.0, 0.0}, CellState::free);
  grid.set(4, 4, CellState::occupied);
  grid.set(10, 10, CellState::unknown);
  const SquareCaster occupied(grid, RayStop::occupied);
  const SquareCaster not_free(grid, RayStop::occupied_or_unknown);
  EXPECT_EQ(occupied.range({2.2, 2.3}, 1.0, 5.0), 0.0);
  EXPECT_EQ(not_free.range({5.2, 5.3}, 1.0, 5.0), 0.0);
  EXPECT_EQ(occupied.range({5.2, 5.3}, 1.0, 5.0), 5.0);  // unknown stops only the other
}

TEST(SquareCaster, OriginOutsideTheGridGivesMaxRange) {
  OccupancyGrid grid(20, 20, 0.5, {0.0, 0.0}, CellState::occupied);
  const SquareCaster caster(grid, RayStop::occupied);
  EXPECT_EQ(caster.range({-0.1, 5.0}, 0.0, 5.0), 5.0);
  EXPECT_EQ(caster.range({5.0, 10.0}, -1.0, 5.0), 5.0);  // on the far edge is outside
  EXPECT_EQ(caster.range({5.0, 5.0}, 0.0, 5.0), 0.0);
}

TEST(SquareCaster, ClearAroundIsTheClearSquareOfAPointsCell) {
  OccupancyGrid lone(30, 30, 0.5, {-5.0, -5.0}, CellState::free);
  lone.set(10, 10, CellState::occupied);
  const SquareCaster caster(lone, RayStop::occupied);
  EXPECT_DOUBLE_EQ(caster.clear_around({-5.0 + 14.2 * 0.5, -5.0 + 10.5 * 0.5}), 1.5);  // 4 cells off: 3 clear
  EXPECT_DOUBLE_EQ(caster.clear_around({-5.0 + 11.5 * 0.5, -5.0 + 9.5 * 0.5}), 0.0);   // the next cell
  EXPECT_EQ(caster.clear_around({-5.0 + 10.5 * 0.5, -5.0 + 10.5 * 0.5}), 0.0);  // in the wall
  EXPECT_EQ(caster.clear_around({-6.0, 0.0}), 0.0);                              // off the grid
  // In the rooms: no stopping cell overlaps the square it promises.
  const OccupancyGrid grid = rooms();
  const SquareCaster rooms_caster(grid, RayStop::occupied_or_unknown);
  std::mt19937 random(8);
  std::uniform_real_distribution<double> x(-2.0, -2.0 + grid.width() * 0.05), y(-1.0, -1.0 + grid.height() * 0.05);
  int roomy = 0;
  for (int i = 0; i < 2000; ++i) {
    const Eigen::Vector2d point{x(random), y(random)};
    const double clear = rooms_caster.clear_around(point);
    roomy += clear > 0.3;
    if (clear == 0.0) continue;  // nothing promised
    const Eigen::Vector2i low = grid.world_to_cell(point - Eigen::Vector2d::Constant(clear - 1e-9));
    const Eigen::Vector2i high = grid.world_to_cell(point + Eigen::Vector2d::Constant(clear - 1e-9));
    for (int row = std::max(low.y(), 0); row <= std::min(high.y(), grid.height() - 1); ++row) {
      for (int col = std::max(low.x(), 0); col <= std::min(high.x(), grid.width() - 1); ++col) {
        ASSERT_EQ(grid.at(col, row), CellState::free) << point.transpose() << " clear " << clear;
      }
    }
  }
  EXPECT_GT(roomy, 200);
}

TEST(SquareCaster, ABatchNeedsRoomForEveryRange) {
  const SquareCaster caster(OccupancyGrid(10, 10, 0.1, {0.0, 0.0}, CellState::free), RayStop::occupied);
  std::vector<SquareCaster::Ray> rays(3, {.origin = {0.5, 0.5}, .direction = {1.0, 0.0}, .max_range = 2.0});
  std::vector<double> ranges(2);
  EXPECT_THROW(caster.ranges(rays, ranges), std::invalid_argument);
  ranges.resize(3);
  caster.ranges(rays, ranges);
  EXPECT_EQ(ranges, std::vector<double>(3, 2.0));  // leaves the 1 m grid: max_range
  caster.ranges({}, {});
}

TEST(SquareCaster, DegenerateInputsAsCastRay) {
  OccupancyGrid grid(20, 20, 0.5, {0.0, 0.0}, CellState::free);
  grid.set(12, 4, CellState::occupied);
  const SquareCaster caster(grid, RayStop::occupied);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double infinity = std::numeric_limits<double>::infinity();
  EXPECT_EQ(caster.range({2.0, 2.0}, 0.0, 0.0), 0.0);
  EXPECT_EQ(caster.range({2.0, 2.0}, 0.0, -1.0), -1.0);
  EXPECT_TRUE(std::isnan(caster.range({2.0, 2.0}, 0.0, nan)));
  EXPECT_EQ(caster.range({nan, 2.0}, 0.0, 5.0), 5.0);
  EXPECT_EQ(caster.range({2.0, 2.0}, nan, 5.0), 5.0);
  EXPECT_EQ(caster.range({2.0, 2.0}, Eigen::Vector2d::Zero(), 5.0), 5.0);
  EXPECT_NEAR(caster.range({2.0, 2.2}, 0.0, infinity), 4.0, 1e-12);  // x = 6.0 is where cell 12 starts
  EXPECT_EQ(caster.range({2.0, 2.2}, std::numbers::pi, infinity), infinity);
  EXPECT_EQ(SquareCaster().range({0.0, 0.0}, 0.0, 5.0), 5.0);
  EXPECT_EQ(SquareCaster(OccupancyGrid(), RayStop::occupied).range({0.0, 0.0}, 0.0, 5.0), 5.0);
}

// Where the processor has it, the batch walks take the vector walker; the
// machines this project builds on do (x86-64 with AVX2), so that the tests
// above compare it with the scalar walks.
TEST(SquareCaster, TheVectorWalkerIsTakenWhereThereIsOne) {
#if defined(__x86_64__)
  if (!__builtin_cpu_supports("avx2")) GTEST_SKIP() << "this processor has no AVX2";
  EXPECT_TRUE(SquareCaster::has_vector_walker());
#else
  EXPECT_FALSE(SquareCaster::has_vector_walker());
#endif
}

// A fan (one origin, one max_range) gives ranges()'s answers bit for bit,
// whichever walker, from origins in clear cells, in walls, off the grid,
// and for directions that are not finite or have no length.
TEST(SquareCaster, AFanAnswersAsItsRaysDo) {
  const OccupancyGrid grid = rooms();
  std::mt19937 random(99);
  std::uniform_real_distribution<double> x(-2.5, 4.5), y(-1.5, 4.0), angle(-std::numbers::pi, std::numbers::pi);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  int walls = 0, zeros = 0;
  for (const RayStop stop : kBothStops) {
    const SquareCaster caster(grid, stop);
    for (int fan = 0; fan < 60; ++fan) {
      const Eigen::Vector2d origin{x(random), y(random)};
      const double max_range = fan % 7 == 0 ? 0.0 : 0.5 + 0.1 * fan;
      const std::size_t count = fan % 3 == 0 ? 9 : 181;  // a few rays take the scalar walk
      std::vector<Eigen::Vector2d> directions;
      std::vector<SquareCaster::Ray> rays;
      for (std::size_t i = 0; i < count; ++i) {
        const double a = angle(random);
        Eigen::Vector2d direction{std::cos(a), std::sin(a)};
        if (i == 3) direction = {nan, 0.0};
        if (i == 5) direction = Eigen::Vector2d::Zero();
        directions.push_back(direction);
        rays.push_back({origin, direction, max_range});
      }
      for (const auto walker : {SquareCaster::Walker::automatic, SquareCaster::Walker::scalar}) {
        std::vector<double> by_fan(count), by_rays(count);
        caster.fan_ranges(origin, directions, max_range, by_fan, walker);
        caster.ranges(rays, by_rays, SquareCaster::Walker::scalar);
        for (std::size_t i = 0; i < count; ++i) {
          ASSERT_EQ(by_fan[i], by_rays[i]) << "fan " << fan << " ray " << i;
          walls += by_fan[i] > 0.0 && by_fan[i] < max_range;
          zeros += by_fan[i] == 0.0 && max_range > 0.0;
        }
      }
    }
  }
  EXPECT_GT(walls, 5000);
  EXPECT_GT(zeros, 100);  // origins in stopping cells
  const SquareCaster caster(grid, RayStop::occupied);
  std::vector<double> too_few(1);
  EXPECT_THROW(caster.fan_ranges({0.0, 0.0}, std::vector<Eigen::Vector2d>(2), 1.0, too_few), std::invalid_argument);
}

// clear_around reads the Chebyshev clearance the constructor computes: here
// against brute force, cell by cell, on random grids (both stop rules, and
// a grid wider than the 255-cell cap).
TEST(SquareCaster, ClearAroundIsTheChebyshevDistanceToTheNearestStoppingCell) {
  std::mt19937 random(9);
  for (const auto& [width, height, blobs] : {std::tuple{40, 30, 12}, std::tuple{300, 7, 2}, std::tuple{1, 1, 0}}) {
    OccupancyGrid grid(width, height, 0.1, {-1.0, 2.0}, CellState::free);
    std::uniform_int_distribution<int> col(0, width - 1), row(0, height - 1), kind(0, 2);
    for (int b = 0; b < blobs; ++b) {
      // One draw per statement: a call's arguments go in an unspecified order.
      const int c = col(random);
      const int r = row(random);
      grid.set(c, r, kind(random) == 0 ? CellState::unknown : CellState::occupied);
    }
    for (const RayStop stop : {RayStop::occupied, RayStop::occupied_or_unknown}) {
      const SquareCaster caster(grid, stop);
      for (int r = 0; r < height; ++r) {
        for (int c = 0; c < width; ++c) {
          int nearest = 255;
          for (int r2 = 0; r2 < height; ++r2) {
            for (int c2 = 0; c2 < width; ++c2) {
              const CellState state = grid.at(c2, r2);
              const bool stops = state == CellState::occupied || (stop == RayStop::occupied_or_unknown && state == CellState::unknown);
              if (stops) nearest = std::min(nearest, std::max(std::abs(c2 - c), std::abs(r2 - r)));
            }
          }
          const Eigen::Vector2d centre = grid.origin() + Eigen::Vector2d(c + 0.5, r + 0.5) * grid.resolution();
          const double expected = nearest == 0 ? 0.0 : (nearest - 1) * grid.resolution();
          ASSERT_DOUBLE_EQ(caster.clear_around(centre), expected) << width << "x" << height << " cell " << c << "," << r;
        }
      }
    }
  }
}

}  // namespace square_caster_test
}  // namespace playerkit::grid
