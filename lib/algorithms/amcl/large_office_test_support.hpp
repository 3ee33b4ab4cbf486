#pragma once
// A large office floor for global-localization tests and benchmarks: a
// building of corridors crossing at irregular spacings, blocks between them
// divided into rooms of random widths with a door each onto a corridor,
// furniture in some rooms, and a robot driving a random route along the
// corridors with drifting odometry and a noisy laser. Everything is drawn
// from one seed. Irregular block, room and door sizes keep the floor from
// mapping onto itself, but long stretches of corridor still look alike for
// metres, which is what makes a global start hard at this scale. Walls are
// the faces a laser sees, unknown behind, as in a map made from scans.

#include "algorithms/amcl/laser_scan.hpp"
#include "algorithms/amcl/synthetic_room_test_support.hpp"
#include "algorithms/geometry/pose2.hpp"
#include "algorithms/grid/occupancy_grid.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <random>
#include <vector>

namespace playerkit::amcl::test {

// Sets every cell whose centre lies in [x0, x1] x [y0, y1] (m), touching
// only those cells: a floor of millions of cells is built in milliseconds.
inline void fill_rectangle(grid::OccupancyGrid& map, double x0, double y0, double x1, double y1,
                           grid::CellState state) {
  const double r = map.resolution();
  const auto first = [&](double v, double origin) { return static_cast<int>(std::ceil((v - origin) / r - 0.5)); };
  const auto last = [&](double v, double origin) { return static_cast<int>(std::floor((v - origin) / r - 0.5)); };
  const int col0 = std::max(0, first(x0, map.origin().x()));
  const int col1 = std::min(map.width() - 1, last(x1, map.origin().x()));
  const int row0 = std::max(0, first(y0, map.origin().y()));
  const int row1 = std::min(map.height() - 1, last(y1, map.origin().y()));
  for (int row = row0; row <= row1; ++row) {
    for (int col = col0; col <= col1; ++col) map.set(col, row, state);
  }
}

struct LargeOfficeSpec {
  double width = 150.0, height = 150.0;  // m, the building's outline
  double resolution = 0.1;               // m per cell
  double block_least = 16.0, block_most = 30.0;          // m between corridors
  double corridor_least = 1.8, corridor_most = 3.0;      // m, corridor widths
  double room_least = 3.5, room_most = 9.0;              // m, room widths along a corridor
  double door_least = 0.9, door_most = 1.4;              // m
  double furnished_share = 0.5;  // rooms with a table or cabinet in them
  double corridor_feature_spacing = 6.0;  // m, mean gap between things along a corridor wall
};

struct LargeOffice {
  std::shared_ptr<grid::OccupancyGrid> map;
  // Corridor centre lines: vertical corridors' x and horizontal ones' y (m).
  std::vector<double> corridor_x, corridor_y;
  double free_area = 0.0;  // m^2
};

// One axis's corridors: [start, end) intervals across [margin, length -
// margin], blocks of block_least-block_most between them.
inline std::vector<std::pair<double, double>> corridor_spans(double length, const LargeOfficeSpec& spec,
                                                             std::mt19937_64& rng) {
  std::uniform_real_distribution<double> width(spec.corridor_least, spec.corridor_most);
  std::uniform_real_distribution<double> block(spec.block_least, spec.block_most);
  constexpr double margin = 1.0;
  std::vector<std::pair<double, double>> spans;
  double at = margin;
  while (true) {
    const double w = width(rng);
    spans.emplace_back(at, at + w);
    at += w;
    const double next = block(rng);
    if (at + next + spec.corridor_most + margin > length) break;
    at += next;
  }
  // The last corridor runs along the far wall, so every block has corridors on both sides.
  const double w = width(rng);
  const double end = length - margin;
  if (spans.back().second + 4.0 < end - w) spans.emplace_back(end - w, end);
  return spans;
}

inline LargeOffice make_large_office(std::uint64_t seed, const LargeOfficeSpec& spec = {}) {
  std::mt19937_64 rng(seed);
  const int width = static_cast<int>(std::lround(spec.width / spec.resolution));
  const int height = static_cast<int>(std::lround(spec.height / spec.resolution));
  LargeOffice office;
  office.map = std::make_shared<grid::OccupancyGrid>(width, height, spec.resolution, Eigen::Vector2d::Zero(),
                                                     grid::CellState::occupied);
  grid::OccupancyGrid& map = *office.map;
  const auto xs = corridor_spans(spec.width, spec, rng);
  const auto ys = corridor_spans(spec.height, spec, rng);
  for (const auto& [x0, x1] : xs) {
    fill_rectangle(map, x0, ys.front().first, x1, ys.back().second, grid::CellState::free);
    office.corridor_x.push_back(0.5 * (x0 + x1));
  }
  for (const auto& [y0, y1] : ys) {
    fill_rectangle(map, xs.front().first, y0, xs.back().second, y1, grid::CellState::free);
    office.corridor_y.push_back(0.5 * (y0 + y1));
  }

  constexpr double wall = 0.2;
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto between = [&](double low, double high) { return low + (high - low) * unit(rng); };
  // A row of rooms along a corridor: the row spans [a0, a1] along the
  // corridor and [b0, b1] across it; the doors open at b = door_side.
  const auto room_row = [&](bool along_x, double a0, double a1, double b0, double b1, double door_side) {
    const auto carve = [&](double p0, double q0, double p1, double q1) {
      if (along_x) {
        fill_rectangle(map, p0, q0, p1, q1, grid::CellState::free);
      } else {
        fill_rectangle(map, q0, p0, q1, p1, grid::CellState::free);
      }
    };
    const auto place = [&](double p0, double q0, double p1, double q1, grid::CellState state) {
      if (along_x) {
        fill_rectangle(map, p0, q0, p1, q1, state);
      } else {
        fill_rectangle(map, q0, p0, q1, p1, state);
      }
    };
    double at = a0 + wall;
    while (at + spec.room_least <= a1 - wall) {
      double room = between(spec.room_least, spec.room_most);
      if (a1 - wall - (at + room) < spec.room_least) room = a1 - wall - at;  // the last takes the rest
      const double r0 = at, r1 = at + room;
      carve(r0, b0 + wall, r1, b1 - wall);
      const double door = between(spec.door_least, std::min(spec.door_most, room - 0.4));
      const double door_at = between(r0 + 0.2, r1 - 0.2 - door);
      const bool low_side = door_side < b0 + 0.5 * (b1 - b0);
      carve(door_at, low_side ? b0 - 0.05 : b1 - wall - 0.05, door_at + door, low_side ? b0 + wall + 0.05 : b1 + 0.05);
      if (unit(rng) < spec.furnished_share) {
        const double depth = b1 - b0 - 2 * wall;
        const double fa = between(0.6, std::min(2.5, room - 1.5));
        const double fb = between(0.6, std::min(1.8, depth - 2.0));
        if (fa > 0.5 && fb > 0.5) {
          const double p = between(r0 + 0.6, r1 - 0.6 - fa);
          // Away from the door's side, so the way in stays open.
          const double q = low_side ? between(b0 + wall + 1.4, b1 - wall - 0.4 - fb)
                                    : between(b0 + wall + 0.4, b1 - wall - 1.4 - fb);
          place(p, q, p + fa, q + fb, grid::CellState::occupied);
        }
      }
      at = r1 + wall;
    }
  };
  for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
    for (std::size_t j = 0; j + 1 < ys.size(); ++j) {
      const double x0 = xs[i].second, x1 = xs[i + 1].first;
      const double y0 = ys[j].second, y1 = ys[j + 1].first;
      // Rooms face the corridors along the block's longer sides; a shallow
      // block is one row of rooms, a deep one two, back to back.
      const bool along_x = (x1 - x0) >= (y1 - y0);
      const double a0 = along_x ? x0 : y0, a1 = along_x ? x1 : y1;
      const double b0 = along_x ? y0 : x0, b1 = along_x ? y1 : x1;
      if (b1 - b0 < 12.0) {
        room_row(along_x, a0, a1, b0, b1, unit(rng) < 0.5 ? b0 : b1);
      } else {
        const double split = between(b0 + 0.4 * (b1 - b0), b0 + 0.6 * (b1 - b0));
        room_row(along_x, a0, a1, b0, split, b0);
        room_row(along_x, a0, a1, split, b1, b1);
      }
    }
  }
  // Along the corridor walls, between crossings: cabinets, pillars and
  // printers standing out into the corridor every few metres, as real
  // corridors have; without them a corridor looks the same for tens of
  // metres and even tracking slides along it. At most a third of the
  // corridor's width, so the way along its middle stays free.
  const auto furnish_corridor = [&](bool along_x, double a0, double a1, double b0, double b1) {
    for (const bool low_side : {true, false}) {
      double at = a0 + between(1.0, spec.corridor_feature_spacing);
      while (at + 1.5 < a1) {
        const double length = between(0.4, 1.5);
        const double depth = between(0.2, (b1 - b0) / 3.0);
        const double q0 = low_side ? b0 - 0.05 : b1 - depth;
        const double q1 = low_side ? b0 + depth : b1 + 0.05;
        if (along_x) {
          fill_rectangle(map, at, q0, at + length, q1, grid::CellState::occupied);
        } else {
          fill_rectangle(map, q0, at, q1, at + length, grid::CellState::occupied);
        }
        at += length + between(1.0, 2.0 * spec.corridor_feature_spacing);
      }
    }
  };
  for (std::size_t i = 0; i < xs.size(); ++i) {
    for (std::size_t j = 0; j + 1 < ys.size(); ++j) furnish_corridor(false, ys[j].second, ys[j + 1].first, xs[i].first, xs[i].second);
  }
  for (std::size_t j = 0; j < ys.size(); ++j) {
    for (std::size_t i = 0; i + 1 < xs.size(); ++i) furnish_corridor(true, xs[i].second, xs[i + 1].first, ys[j].first, ys[j].second);
  }
  // As a map made from scans has it: obstacles are what a laser saw, the
  // faces next to free space; behind them is unknown. A floor solid
  // behind every wall would score a pose inside a wall block perfectly
  // (every endpoint on an obstacle), a trap no real map sets.
  const grid::OccupancyGrid carved = map;
  for (int row = 0; row < map.height(); ++row) {
    for (int col = 0; col < map.width(); ++col) {
      if (carved.at(col, row) == grid::CellState::free) continue;
      bool faces_free = false;
      for (int dr = -1; dr <= 1 && !faces_free; ++dr) {
        for (int dc = -1; dc <= 1 && !faces_free; ++dc) {
          faces_free = carved.contains(col + dc, row + dr) && carved.at(col + dc, row + dr) == grid::CellState::free;
        }
      }
      map.set(col, row, faces_free ? grid::CellState::occupied : grid::CellState::unknown);
    }
  }
  std::size_t free_cells = 0;
  for (const grid::CellState cell : map.cells()) free_cells += cell == grid::CellState::free ? 1 : 0;
  office.free_area = static_cast<double>(free_cells) * spec.resolution * spec.resolution;
  return office;
}

// What the robot logged at one step, and where it really was.
struct LoggedStep {
  geometry::Pose2 truth;
  geometry::Pose2 odometry;
  LaserScan scan;
};

struct OfficeDriveSpec {
  std::size_t legs = 8;          // corridor intersections visited
  double step = 0.1;             // m per logged step (a 10 Hz log at 1 m/s)
  double turn_step = 0.25;       // rad per logged step when turning
  LaserSpec laser{.beams = 181, .field_of_view = std::numbers::pi, .max_range = 20.0,
                  .sensor_pose = {0.1, 0.0, 0.0}};
  double range_noise = 0.02;     // m
  double odometry_scale_error = 0.02;  // systematic, per run
  double odometry_gain_noise = 0.03;   // per step, relative
  double odometry_slip = 0.002;        // rad per step
};

// A random route along the corridors, from one intersection to a
// neighbouring one (never straight back), starting half way along a
// corridor; a scan at every step.
inline std::vector<LoggedStep> drive_large_office(const LargeOffice& office, std::uint64_t seed,
                                                  const OfficeDriveSpec& spec = {}) {
  std::mt19937_64 rng(seed);
  const auto pick = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); };
  const std::size_t nx = office.corridor_x.size(), ny = office.corridor_y.size();
  std::size_t ix = pick(nx), iy = pick(ny - 1);
  std::vector<Eigen::Vector2d> route;
  const Eigen::Vector2d start(office.corridor_x[ix], 0.5 * (office.corridor_y[iy] + office.corridor_y[iy + 1]));
  if (pick(2) == 0) ++iy;
  int last_dx = 0, last_dy = 0;
  for (std::size_t leg = 0; leg < spec.legs; ++leg) {
    route.emplace_back(office.corridor_x[ix], office.corridor_y[iy]);
    std::vector<std::pair<int, int>> moves;
    for (const auto& [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
      const long x = static_cast<long>(ix) + dx, y = static_cast<long>(iy) + dy;
      if (x < 0 || y < 0 || x >= static_cast<long>(nx) || y >= static_cast<long>(ny)) continue;
      if (dx == -last_dx && dy == -last_dy) continue;
      moves.emplace_back(dx, dy);
    }
    const auto [dx, dy] = moves[pick(moves.size())];
    ix = static_cast<std::size_t>(static_cast<long>(ix) + dx);
    iy = static_cast<std::size_t>(static_cast<long>(iy) + dy);
    last_dx = dx;
    last_dy = dy;
  }

  const Eigen::Vector2d first = route.front() - start;
  geometry::Pose2 truth{start.x(), start.y(), std::atan2(first.y(), first.x())};
  geometry::Pose2 odometry{-3.0, 7.0, 0.4};  // a frame unrelated to the map's
  std::normal_distribution<double> gain(1.0, spec.odometry_gain_noise), slip(0.0, spec.odometry_slip);
  const double scale = 1.0 + spec.odometry_scale_error * (pick(2) == 0 ? 1.0 : -1.0);
  std::vector<LoggedStep> log;
  const auto record = [&] {
    log.push_back({truth, odometry, simulate_scan(*office.map, truth, spec.laser, spec.range_noise, &rng)});
  };
  const auto move = [&](const geometry::Pose2& delta) {
    truth = truth.compose(delta);
    const geometry::Pose2 measured{delta.x * scale * gain(rng), delta.y * scale * gain(rng),
                                   delta.yaw * gain(rng) + slip(rng)};
    odometry = odometry.compose(measured);
    record();
  };
  record();
  for (const Eigen::Vector2d& goal : route) {
    while (true) {
      const Eigen::Vector2d to_goal = goal - truth.translation();
      if (to_goal.norm() < 0.02) break;  // close enough: a tiny remainder would need a turn on the spot
      const double turn = geometry::angle_difference(std::atan2(to_goal.y(), to_goal.x()), truth.yaw);
      if (std::abs(turn) > 0.05) {
        move({0.0, 0.0, std::clamp(turn, -spec.turn_step, spec.turn_step)});
      } else {
        move({std::min(spec.step, to_goal.norm()), 0.0, turn});
      }
    }
  }
  return log;
}

}  // namespace playerkit::amcl::test
