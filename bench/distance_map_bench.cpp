// Speed of lib/algorithms/grid on large maps, on one core:
//   * DistanceMap construction (exact Euclidean transform) on N x N grids,
//     N = 1000, 2000, 4000 (the 4000 x 4000 figure answers issue 6);
//   * cast_ray throughput (rays/s) on the 4000 x 4000 map, 30 m rays, and
//     RangeCaster's and SquareCaster's on the same rays, from anywhere or
//     from a 2 m cloud, and the casters' builds;
//   * OccupancyGridBuilder::add_scan throughput (scans/s, 361 beams).
//
//   ./build/bench/distance_map_bench --benchmark_counters_tabular=true
//
// The maps are 0.05 m cells, free, with random straight walls 1-10 m long
// and a sprinkle of single-cell clutter (fixed seed), a stand-in for a
// building floor; cells outside walls are free, so rays run long.

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstddef>
#include <map>
#include <numbers>
#include <random>
#include <vector>

#include "algorithms/geometry/pose2.hpp"
#include "algorithms/grid/distance_map.hpp"
#include "algorithms/grid/occupancy_grid.hpp"
#include "algorithms/grid/occupancy_grid_builder.hpp"
#include "algorithms/grid/range_caster.hpp"
#include "algorithms/grid/ray_cast.hpp"
#include "algorithms/grid/square_caster.hpp"

namespace playerkit::grid {
namespace {

constexpr double kResolution = 0.05;

OccupancyGrid make_building(int size) {
  OccupancyGrid grid = OccupancyGrid::centred(size, size, kResolution, CellState::free);
  std::mt19937 random(42);
  std::uniform_int_distribution<int> cell(0, size - 1);
  std::uniform_int_distribution<int> length(20, 200);
  std::bernoulli_distribution horizontal(0.5);
  const int walls = size * size / 8000;  // ~2000 on 4000 x 4000
  for (int i = 0; i < walls; ++i) {
    const int col = cell(random), row = cell(random), n = length(random);
    const bool along_x = horizontal(random);
    for (int k = 0; k < n; ++k) {
      const int c = along_x ? col + k : col, r = along_x ? row : row + k;
      if (grid.contains(c, r)) grid.set(c, r, CellState::occupied);
    }
  }
  const int clutter = size * size / 2000;
  for (int i = 0; i < clutter; ++i) grid.set(cell(random), cell(random), CellState::occupied);
  return grid;
}

const OccupancyGrid& building(int size) {
  static std::map<int, OccupancyGrid> cache;
  auto found = cache.find(size);
  if (found == cache.end()) found = cache.emplace(size, make_building(size)).first;
  return found->second;
}

void BM_DistanceMap(benchmark::State& state) {
  const int size = static_cast<int>(state.range(0));
  const OccupancyGrid& grid = building(size);
  for (auto _ : state) {
    DistanceMap map(grid, 2.0);
    benchmark::DoNotOptimize(map.at(size / 2, size / 2));
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(size) * size);
  state.counters["cells"] = static_cast<double>(size) * size;
}
BENCHMARK(BM_DistanceMap)->ArgName("N")->Arg(1000)->Arg(2000)->Arg(4000)->Unit(benchmark::kMillisecond)->UseRealTime();

// 4096 random 30 m rays on the 4000 x 4000 map (fixed seed), shared by the
// cast_ray and RangeCaster benchmarks so their figures compare. Origins
// either anywhere on the map (every ray starts in cold memory) or in a 2 m
// square, as a particle cloud's are (the map around it stays in cache).
struct Rays {
  std::vector<Eigen::Vector2d> origins;
  std::vector<double> angles;
};

const Rays& random_rays(bool in_a_cloud) {
  const auto make = [](double half_width) {
    Rays made;
    std::mt19937 random(7);
    std::uniform_real_distribution<double> coordinate(-half_width, half_width);
    std::uniform_real_distribution<double> angle(-std::numbers::pi, std::numbers::pi);
    for (int i = 0; i < 4096; ++i) {
      made.origins.emplace_back(coordinate(random), coordinate(random));
      made.angles.push_back(angle(random));
    }
    return made;
  };
  static const Rays anywhere = make(90.0), cloud = make(1.0);
  return in_a_cloud ? cloud : anywhere;
}

template <typename Cast>
double mean_over_all(const Rays& rays, const Cast& cast) {
  double total = 0.0;
  for (std::size_t k = 0; k < rays.angles.size(); ++k) total += cast(k);
  return total / static_cast<double>(rays.angles.size());
}

// Both ray benchmarks: the same 4096 rays over and over, and their mean range
// as a counter, which must be equal between the two (to the printed digits).
template <typename Cast>
void time_rays(benchmark::State& state, const Rays& rays, const Cast& cast) {
  state.counters["mean_range_m"] = mean_over_all(rays, cast);
  std::size_t i = 0;
  double total_range = 0.0;
  for (auto _ : state) total_range += cast(i++ & 4095);
  benchmark::DoNotOptimize(total_range);
  state.SetItemsProcessed(state.iterations());
}

void BM_CastRay(benchmark::State& state) {
  const OccupancyGrid& grid = building(4000);
  const RayStop stop = state.range(0) ? RayStop::occupied : RayStop::occupied_or_unknown;
  const Rays& rays = random_rays(state.range(1) != 0);
  time_rays(state, rays, [&](std::size_t k) { return cast_ray(grid, rays.origins[k], rays.angles[k], 30.0, stop); });
}
BENCHMARK(BM_CastRay)->ArgNames({"stop_on_occupied_only", "cloud"})->ArgsProduct({{0, 1}, {0, 1}});

// The same rays by ray marching. Building the caster (a distance transform)
// is outside the timed loop.
void BM_RangeCaster(benchmark::State& state) {
  const OccupancyGrid& grid = building(4000);
  const RayStop stop = state.range(0) ? RayStop::occupied : RayStop::occupied_or_unknown;
  const RangeCaster caster(grid, stop);
  const Rays& rays = random_rays(state.range(1) != 0);
  time_rays(state, rays, [&](std::size_t k) { return caster.range(rays.origins[k], rays.angles[k], 30.0); });
}
BENCHMARK(BM_RangeCaster)->ArgNames({"stop_on_occupied_only", "cloud"})->ArgsProduct({{0, 1}, {0, 1}});

// The same rays by clear squares (SquareCaster), one by one and all 4096
// in one call (two walked side by side). Its build is outside the loop.
void BM_SquareCaster(benchmark::State& state) {
  const OccupancyGrid& grid = building(4000);
  const RayStop stop = state.range(0) ? RayStop::occupied : RayStop::occupied_or_unknown;
  const SquareCaster caster(grid, stop);
  const Rays& rays = random_rays(state.range(1) != 0);
  time_rays(state, rays, [&](std::size_t k) { return caster.range(rays.origins[k], rays.angles[k], 30.0); });
}
BENCHMARK(BM_SquareCaster)->ArgNames({"stop_on_occupied_only", "cloud"})->ArgsProduct({{0, 1}, {0, 1}});

void BM_SquareCasterBatch(benchmark::State& state) {
  const OccupancyGrid& grid = building(4000);
  const RayStop stop = state.range(0) ? RayStop::occupied : RayStop::occupied_or_unknown;
  const SquareCaster caster(grid, stop);
  const Rays& rays = random_rays(state.range(1) != 0);
  std::vector<SquareCaster::Ray> batch;
  for (std::size_t k = 0; k < rays.angles.size(); ++k) {
    batch.push_back({rays.origins[k], {std::cos(rays.angles[k]), std::sin(rays.angles[k])}, 30.0});
  }
  std::vector<double> ranges(batch.size());
  for (auto _ : state) {
    caster.ranges(batch, ranges);
    benchmark::DoNotOptimize(ranges.data());
  }
  double total = 0.0;
  for (const double range : ranges) total += range;
  state.counters["mean_range_m"] = total / static_cast<double>(ranges.size());
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(batch.size()));
}
BENCHMARK(BM_SquareCasterBatch)->ArgNames({"stop_on_occupied_only", "cloud"})->ArgsProduct({{0, 1}, {0, 1}});

// The casters' builds on the 4000 x 4000 map.
void BM_BuildRangeCaster(benchmark::State& state) {
  const OccupancyGrid& grid = building(4000);
  for (auto _ : state) benchmark::DoNotOptimize(RangeCaster(grid, RayStop::occupied).stop());
}
BENCHMARK(BM_BuildRangeCaster)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_BuildSquareCaster(benchmark::State& state) {
  const OccupancyGrid& grid = building(4000);
  for (auto _ : state) benchmark::DoNotOptimize(SquareCaster(grid, RayStop::occupied).stop());
}
BENCHMARK(BM_BuildSquareCaster)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_BuilderAddScan(benchmark::State& state) {
  const OccupancyGrid& grid = building(2000);  // 100 m x 100 m
  constexpr int kBeams = 361;
  std::mt19937 random(11);
  std::uniform_real_distribution<double> coordinate(-45.0, 45.0);
  std::uniform_real_distribution<double> yaw(-std::numbers::pi, std::numbers::pi);
  std::vector<geometry::Pose2> poses;
  std::vector<std::vector<double>> scans;
  for (int i = 0; i < 256; ++i) {
    const geometry::Pose2 pose{coordinate(random), coordinate(random), yaw(random)};
    std::vector<double> ranges(kBeams);
    for (int b = 0; b < kBeams; ++b) {
      ranges[static_cast<std::size_t>(b)] =
          cast_ray(grid, pose.translation(), pose.yaw - std::numbers::pi / 2 + b * std::numbers::pi / 360, 30.0,
                   RayStop::occupied);
    }
    poses.push_back(pose);
    scans.push_back(std::move(ranges));
  }
  OccupancyGridBuilder builder;
  std::size_t i = 0;
  for (auto _ : state) {
    const std::size_t k = i++ & 255;
    builder.add_scan(poses[k], scans[k], -std::numbers::pi / 2, std::numbers::pi / 360, 30.0);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_BuilderAddScan)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace playerkit::grid

BENCHMARK_MAIN();
