// Speed of one VFH step (lib/algorithms/vfh) at the defaults (61 x 61
// window of 0.1 m, 5-degree sectors) on scans of a cluttered room: a 361-
// and a 181-reading laser, and a window of 121 cells for comparison. The
// issue's target is 1 ms a cycle.
//
//   ./build/bench/vfh_bench --benchmark_counters_tabular=true

#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "algorithms/grid/occupancy_grid.hpp"
#include "algorithms/grid/ray_cast.hpp"
#include "algorithms/vfh/vfh_planner.hpp"

namespace playerkit::vfh {
namespace {

// 12 m x 12 m of 5 cm cells, walls round it and 40 boxes of 0.3 m scattered.
grid::OccupancyGrid cluttered_room() {
  grid::OccupancyGrid room = grid::OccupancyGrid::centred(240, 240, 0.05, grid::CellState::free);
  for (int i = 0; i < 240; ++i) {
    for (const int edge : {0, 239}) {
      room.set(i, edge, grid::CellState::occupied);
      room.set(edge, i, grid::CellState::occupied);
    }
  }
  std::mt19937 random(7);
  std::uniform_int_distribution<int> place(10, 224);
  for (int box = 0; box < 40; ++box) {
    const int x = place(random), y = place(random);
    for (int dx = 0; dx < 6; ++dx) {
      for (int dy = 0; dy < 6; ++dy) room.set(x + dx, y + dy, grid::CellState::occupied);
    }
  }
  return room;
}

std::vector<std::vector<double>> scans(int readings) {
  const grid::OccupancyGrid room = cluttered_room();
  std::vector<std::vector<double>> taken;
  for (int pose = 0; pose < 50; ++pose) {
    const Eigen::Vector2d at(-4.0 + 0.16 * pose, -1.0 + 0.04 * pose);
    const double heading = 0.1 * pose;
    std::vector<double> ranges(static_cast<std::size_t>(readings));
    for (int i = 0; i < readings; ++i) {
      const double bearing = -std::numbers::pi / 2 + std::numbers::pi * i / (readings - 1);
      ranges[static_cast<std::size_t>(i)] = grid::cast_ray(room, at, heading + bearing, 8.0);
    }
    taken.push_back(std::move(ranges));
  }
  return taken;
}

void VfhStep(benchmark::State& state) {
  const int readings = static_cast<int>(state.range(0));
  VfhParameters parameters;
  parameters.window_diameter = static_cast<int>(state.range(1));
  VfhPlanner planner(parameters);
  const auto taken = scans(readings);
  std::size_t next = 0;
  for (auto _ : state) {
    const std::vector<double>& ranges = taken[next++ % taken.size()];
    const Scan scan{-std::numbers::pi / 2, std::numbers::pi / (readings - 1), ranges};
    benchmark::DoNotOptimize(planner.step(scan, 90, 0.1, 1.0));
  }
  state.counters["us_per_step"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(VfhStep)->Args({361, 61})->Args({181, 61})->Args({361, 121})->Unit(benchmark::kMicrosecond);

void VfhWindow(benchmark::State& state) {
  VfhParameters parameters;
  parameters.window_diameter = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(HistogramWindow(parameters));
}
BENCHMARK(VfhWindow)->Arg(61)->Arg(121)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace playerkit::vfh

BENCHMARK_MAIN();
