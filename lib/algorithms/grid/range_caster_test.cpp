#include "algorithms/grid/range_caster.hpp"

#include "algorithms/grid/ray_cast.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace playerkit::grid {
namespace range_caster_test {

constexpr RayStop kBothStops[] = {RayStop::occupied, RayStop::occupied_or_unknown};

struct Ray {
  Eigen::Vector2d origin;
  double angle;
  double max_range;
};

// cast_ray is the specification; a floating-point difference is all that is
// allowed.
double allowed_error(double max_range) { return 1e-9 * std::max(1.0, max_range); }

// Compares every ray in both stop modes and returns how many of the answers
// were hits (neither max_range nor 0), so callers can check that the rays
// exercised what they meant to.
int expect_same_as_cast_ray(const OccupancyGrid& grid, const std::vector<Ray>& rays,
                            const std::string& what, double max_jump = 10.0) {
  int hits = 0;
  for (const RayStop stop : kBothStops) {
    const RangeCaster caster(grid, stop, max_jump);
    int failures = 0;
    for (const Ray& ray : rays) {
      const double expected = cast_ray(grid, ray.origin, ray.angle, ray.max_range, stop);
      const double actual = caster.range(ray.origin, ray.angle, ray.max_range);
      if (std::abs(actual - expected) > allowed_error(ray.max_range) && failures++ < 5) {
        ADD_FAILURE() << what << (stop == RayStop::occupied ? " (occupied)" : " (not free)")
                      << ": origin (" << ray.origin.x() << ", " << ray.origin.y() << ") angle "
                      << ray.angle << " max_range " << ray.max_range << ": cast_ray " << expected
                      << ", caster " << actual;
      }
      hits += expected > 0.0 && expected < ray.max_range;
    }
    EXPECT_EQ(failures, 0) << what << ": rays differing from cast_ray";
  }
  return hits;
}

// 6 m x 4.5 m at 5 cm: an unknown margin, outer walls, two rooms and a
// corridor joined by doorways, a pillar, and a patch of unknown floor.
OccupancyGrid rooms() {
  OccupancyGrid grid(120, 90, 0.05, {-2.0, -1.0}, CellState::unknown);
  const auto fill = [&](int col0, int row0, int col1, int row1, CellState state) {
    for (int row = row0; row < row1; ++row) {
      for (int col = col0; col < col1; ++col) grid.set(col, row, state);
    }
  };
  fill(4, 4, 116, 86, CellState::occupied);
  fill(6, 6, 114, 84, CellState::free);
  fill(60, 6, 62, 84, CellState::occupied);    // dividing wall, 2 cells thick
  fill(60, 30, 62, 40, CellState::free);       // doorway
  fill(6, 50, 60, 51, CellState::occupied);    // thin wall in the left room
  fill(20, 50, 28, 51, CellState::free);       // doorway
  fill(85, 60, 91, 66, CellState::occupied);   // pillar
  fill(80, 15, 100, 30, CellState::unknown);   // unexplored floor
  fill(114, 40, 116, 44, CellState::free);     // a gap out to the unknown margin
  return grid;
}

OccupancyGrid clutter(unsigned seed) {
  std::mt19937 random(seed);
  std::discrete_distribution<int> state({0.95, 0.02, 0.03});  // free, unknown, occupied
  OccupancyGrid grid(150, 110, 0.1, {3.0, -7.0});
  for (int row = 0; row < grid.height(); ++row) {
    for (int col = 0; col < grid.width(); ++col) {
      grid.set(col, row, static_cast<CellState>(state(random) - 1));
    }
  }
  return grid;
}

// Origins spread over the grid and a margin around it, so some start outside.
std::vector<Ray> random_rays(const OccupancyGrid& grid, int count, unsigned seed,
                             double longest = 12.0, double outside_margin = 1.0) {
  std::mt19937 random(seed);
  const double w = grid.width() * grid.resolution(), h = grid.height() * grid.resolution();
  std::uniform_real_distribution<double> x(grid.origin().x() - outside_margin,
                                           grid.origin().x() + w + outside_margin);
  std::uniform_real_distribution<double> y(grid.origin().y() - outside_margin,
                                           grid.origin().y() + h + outside_margin);
  std::uniform_real_distribution<double> angle(-std::numbers::pi, std::numbers::pi);
  std::uniform_real_distribution<double> range(0.01, longest);
  std::vector<Ray> rays;
  for (int i = 0; i < count; ++i) rays.push_back({{x(random), y(random)}, angle(random), range(random)});
  return rays;
}

// Origins at cell centres and cell corners, along the axes and the
// diagonals and through lattice points (atan2 of small integers), so the
// rays run along cell borders and pass exactly through corners.
std::vector<Ray> lattice_rays(const OccupancyGrid& grid, int step, double max_range) {
  std::vector<double> angles;
  for (int k = -4; k < 4; ++k) angles.push_back(k * std::numbers::pi / 4);
  for (const auto& [dy, dx] : {std::pair{1, 2}, {2, 1}, {-1, 3}, {3, -2}, {-2, -5}}) {
    angles.push_back(std::atan2(dy, dx));
  }
  std::vector<Ray> rays;
  for (int row = 0; row < grid.height(); row += step) {
    for (int col = 0; col < grid.width(); col += step) {
      const Eigen::Vector2i cell(col, row);
      const Eigen::Vector2d corner = grid.origin() + grid.resolution() * cell.cast<double>();
      for (const double angle : angles) {
        rays.push_back({grid.cell_centre(cell), angle, max_range});
        rays.push_back({corner, angle, max_range});
      }
    }
  }
  return rays;
}

TEST(RangeCaster, AgreesWithCastRayInRooms) {
  const OccupancyGrid grid = rooms();
  EXPECT_GT(expect_same_as_cast_ray(grid, random_rays(grid, 4000, 1), "rooms, random rays"), 2000);
  EXPECT_GT(expect_same_as_cast_ray(grid, lattice_rays(grid, 3, 8.0), "rooms, lattice rays"), 10000);
}

TEST(RangeCaster, AgreesWithCastRayInClutter) {
  for (unsigned seed : {11u, 12u}) {
    const OccupancyGrid grid = clutter(seed);
    const std::string name = "clutter " + std::to_string(seed);
    EXPECT_GT(expect_same_as_cast_ray(grid, random_rays(grid, 4000, seed), name + ", random rays"), 2000);
    EXPECT_GT(expect_same_as_cast_ray(grid, lattice_rays(grid, 4, 5.0), name + ", lattice rays"), 10000);
  }
}

TEST(RangeCaster, AgreesWithCastRayWhenJumpsAreCapped) {
  // A cap of 0.3 m (3 cells here) leaves jumps of at most 1.5 cells, right
  // at the edge of jumping at all; answers must not change.
  const OccupancyGrid grid = clutter(13);
  expect_same_as_cast_ray(grid, random_rays(grid, 3000, 13), "clutter, 0.3 m cap", 0.3);
  const OccupancyGrid building = rooms();
  expect_same_as_cast_ray(building, random_rays(building, 3000, 14), "rooms, 0.3 m cap", 0.3);
}

TEST(RangeCaster, AgreesWithCastRayOnAMapWithoutObstacles) {
  const OccupancyGrid grid(200, 120, 0.05, {-5.0, -3.0}, CellState::free);
  const std::vector<Ray> rays = random_rays(grid, 3000, 21, 15.0);
  EXPECT_EQ(expect_same_as_cast_ray(grid, rays, "empty map"), 0);
  // Every ray either leaves the grid or runs out of range: max_range.
  const RangeCaster caster(grid, RayStop::occupied_or_unknown);
  for (const Ray& ray : rays) {
    ASSERT_EQ(caster.range(ray.origin, ray.angle, ray.max_range), ray.max_range);
  }
}

TEST(RangeCaster, WallAtAKnownDistance) {
  // Free 10 m x 4 m at 0.1 m with an occupied column at x in [7.0, 7.1).
  OccupancyGrid grid(100, 40, 0.1, {0.0, 0.0}, CellState::free);
  for (int row = 0; row < 40; ++row) grid.set(70, row, CellState::occupied);
  const RangeCaster caster(grid, RayStop::occupied);
  EXPECT_NEAR(caster.range({0.05, 1.0}, 0.0, 9.0), 6.95, 1e-9);
  EXPECT_NEAR(caster.range({1.0, 0.55}, 0.0, 9.0), 6.0, 1e-9);
  // 60 degrees off the axis the path to the wall is twice as long.
  EXPECT_NEAR(caster.range({6.0, 0.3}, std::numbers::pi / 3, 9.0), 2.0, 1e-9);
  // Looking away the ray leaves the grid: max_range, as cast_ray.
  EXPECT_EQ(caster.range({6.0, 1.0}, std::numbers::pi, 9.0), 9.0);
  // max_range short of the wall.
  EXPECT_EQ(caster.range({1.0, 1.0}, 0.0, 5.9), 5.9);
  EXPECT_NEAR(caster.range({1.0, 1.0}, 0.0, 6.1), 6.0, 1e-9);
}

TEST(RangeCaster, OriginInsideAStoppingCellGivesZero) {
  const OccupancyGrid grid = rooms();
  const RangeCaster not_free(grid, RayStop::occupied_or_unknown);
  const RangeCaster occupied_only(grid, RayStop::occupied);
  const Eigen::Vector2d in_wall = grid.cell_centre({60, 10});
  const Eigen::Vector2d in_unknown_patch = grid.cell_centre({90, 20});
  for (double angle = -3.0; angle < 3.2; angle += 0.5) {
    EXPECT_EQ(not_free.range(in_wall, angle, 8.0), 0.0);
    EXPECT_EQ(occupied_only.range(in_wall, angle, 8.0), 0.0);
    EXPECT_EQ(not_free.range(in_unknown_patch, angle, 8.0), 0.0);
    EXPECT_GT(occupied_only.range(in_unknown_patch, angle, 8.0), 0.2);
  }
}

TEST(RangeCaster, OriginOutsideTheGridGivesMaxRange) {
  const OccupancyGrid grid = rooms();
  const RangeCaster caster(grid, RayStop::occupied);
  // Pointing straight at the map from outside still reads nothing, as cast_ray.
  const Eigen::Vector2d left_of_map = grid.origin() + Eigen::Vector2d(-0.5, 2.0);
  EXPECT_EQ(caster.range(left_of_map, 0.0, 8.0), 8.0);
  EXPECT_EQ(cast_ray(grid, left_of_map, 0.0, 8.0, RayStop::occupied), 8.0);
}

TEST(RangeCaster, DegenerateInputsAsCastRay) {
  const OccupancyGrid grid = rooms();
  const RangeCaster caster(grid, RayStop::occupied);
  const Eigen::Vector2d inside = grid.cell_centre({30, 30});
  EXPECT_EQ(caster.range(inside, 0.3, 0.0), 0.0);
  EXPECT_EQ(caster.range(inside, 0.3, -1.0), -1.0);
  const RangeCaster of_nothing(OccupancyGrid{}, RayStop::occupied);
  EXPECT_EQ(of_nothing.range({0.0, 0.0}, 0.0, 4.0), 4.0);
  EXPECT_THROW(RangeCaster(grid, RayStop::occupied, 0.0), std::invalid_argument);
}

}  // namespace range_caster_test
}  // namespace playerkit::grid
