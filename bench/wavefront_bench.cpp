// Speed of lib/algorithms/wavefront on a 2000 x 2000 map (0.05 m cells,
// 100 m x 100 m), on one core:
//   * SetMap: the per-map work (clearance transform, step costs);
//   * FirstPlan: a planner built and one plan, corner room to corner room;
//   * NewGoal: one more plan on the same planner (the goals alternate);
//   * NearGoal: a goal two rooms away, where the wavefront stops early.
//
//   ./build-wave-rel/bench/wavefront_bench --benchmark_counters_tabular=true
//
// The map is an office floor: 5 m rooms behind 0.15 m walls, a 1 m door in
// every wall at a random place, furniture in the rooms, and a block of
// rooms nobody mapped (unknown). Robot radius 0.15 m, safety 0.15 m, the
// 0.15 m penalty band (the defaults).

#include <benchmark/benchmark.h>

#include <random>

#include "algorithms/grid/occupancy_grid.hpp"
#include "algorithms/wavefront/wavefront_planner.hpp"

namespace playerkit::wavefront {
namespace {

using grid::CellState;
using grid::OccupancyGrid;

constexpr int kSize = 2000;
constexpr int kRoom = 100;  // cells per room side
constexpr int kWall = 3;
constexpr int kDoor = 20;

void fill(OccupancyGrid& grid, int col0, int row0, int col1, int row1, CellState state) {
  for (int row = std::max(row0, 0); row <= std::min(row1, grid.height() - 1); ++row) {
    for (int col = std::max(col0, 0); col <= std::min(col1, grid.width() - 1); ++col) grid.set(col, row, state);
  }
}

OccupancyGrid make_floor() {
  OccupancyGrid grid = OccupancyGrid::centred(kSize, kSize, 0.05, CellState::free);
  std::mt19937 random(42);
  std::uniform_int_distribution<int> door_at(kWall + 5, kRoom - kDoor - 5);
  std::uniform_int_distribution<int> furniture_at(20, kRoom - 25), furniture_size(4, 14), pieces(0, 4);
  for (int line = 0; line <= kSize; line += kRoom) {
    fill(grid, line - 1, 0, line + kWall - 2, kSize - 1, CellState::occupied);  // vertical walls
    fill(grid, 0, line - 1, kSize - 1, line + kWall - 2, CellState::occupied);  // horizontal walls
  }
  for (int a = 0; a < kSize; a += kRoom) {
    for (int b = kRoom; b < kSize; b += kRoom) {
      const int v = a + door_at(random), h = a + door_at(random);
      fill(grid, b - 1, v, b + kWall - 2, v + kDoor - 1, CellState::free);  // door in a vertical wall
      fill(grid, h, b - 1, h + kDoor - 1, b + kWall - 2, CellState::free);  // in a horizontal one
    }
  }
  for (int col = 0; col < kSize; col += kRoom) {
    for (int row = 0; row < kSize; row += kRoom) {
      for (int k = pieces(random); k > 0; --k) {
        const int c = col + furniture_at(random), r = row + furniture_at(random);
        fill(grid, c, r, c + furniture_size(random), r + furniture_size(random), CellState::occupied);
      }
    }
  }
  fill(grid, 1200, 600, 1499, 899, CellState::unknown);  // 3 x 3 rooms never seen
  return grid;
}

const OccupancyGrid& office_floor() {
  static const OccupancyGrid grid = make_floor();
  return grid;
}

// Half a metre from the lower left corner of room (i, j), counted from the
// bottom-left of the floor (world metres): furniture keeps a metre off the walls.
Eigen::Vector2d room(int i, int j) { return {-50.0 + 5.0 * i + 0.5, -50.0 + 5.0 * j + 0.5}; }

void report(benchmark::State& state, const PlanResult& plan) {
  if (!plan.found()) state.SkipWithError(describe_failure(plan, PlannerParameters{}).c_str());
  state.counters["settled_cells"] = static_cast<double>(plan.cells_settled);
  state.counters["waypoints"] = static_cast<double>(plan.waypoints.size());
  state.counters["length_m"] = plan.length_m;
  state.counters["clearance_m"] = plan.min_clearance_m;
}

void BM_SetMap(benchmark::State& state) {
  const OccupancyGrid& grid = office_floor();
  for (auto _ : state) {
    WavefrontPlanner planner(grid);
    benchmark::DoNotOptimize(planner.clearance().at(kSize / 2, kSize / 2));
  }
  state.counters["cells"] = static_cast<double>(kSize) * kSize;
}
BENCHMARK(BM_SetMap)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_FirstPlan(benchmark::State& state) {
  const OccupancyGrid& grid = office_floor();
  PlanResult plan;
  for (auto _ : state) {
    WavefrontPlanner planner(grid);
    plan = planner.plan(room(0, 0), room(19, 19));
  }
  report(state, plan);
}
BENCHMARK(BM_FirstPlan)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_NewGoal(benchmark::State& state) {
  WavefrontPlanner planner(office_floor());
  PlanResult plan;
  int k = 0;
  for (auto _ : state) plan = planner.plan(room(0, 0), ++k % 2 ? room(19, 19) : room(19, 17));
  report(state, plan);
}
BENCHMARK(BM_NewGoal)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_NearGoal(benchmark::State& state) {
  WavefrontPlanner planner(office_floor());
  PlanResult plan;
  for (auto _ : state) plan = planner.plan(room(8, 8), room(10, 9));
  report(state, plan);
}
BENCHMARK(BM_NearGoal)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace playerkit::wavefront

BENCHMARK_MAIN();
