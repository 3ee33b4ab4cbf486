// Cost of one AMCL laser update (motion, weighting, resampling every second
// update, clustering) on one core, for both laser models:
//   - at default settings while tracking (KLD keeps a few hundred particles),
//   - with the particle count pinned at 5000 (min = max), the worst case of
//     a global start.
// The map is a synthetic 40 m x 20 m hall at 5 cm (800 x 400 cells) with a
// row of pillars; scans are 181 beams over 180 degrees, 8 m max range, like
// the Radish SICK logs. The robot shuttles 0.25 m back and forth so every
// update() call passes the 0.2 m threshold and runs a laser update.
// And PoseClusterer::cluster alone, at amcl's bins (0.5 m, 10 degrees), on a
// tracked cloud of 5000 particles and on a global search's 77 000 spread
// over the hall (the count Freiburg 079's search draws).
//
//   ./build/bench/amcl_filter_bench --benchmark_counters_tabular=true

#include "algorithms/amcl/amcl_filter.hpp"
#include "algorithms/amcl/pose_estimate.hpp"
#include "algorithms/grid/ray_cast.hpp"

#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <vector>

namespace {

using playerkit::amcl::AmclFilter;
using playerkit::amcl::AmclParameters;
using playerkit::amcl::LaserModelType;
using playerkit::amcl::LaserScan;
using playerkit::geometry::Pose2;
namespace grid = playerkit::grid;

std::shared_ptr<grid::OccupancyGrid> make_hall() {
  auto map = std::make_shared<grid::OccupancyGrid>(800, 400, 0.05, Eigen::Vector2d(0.0, 0.0),
                                                   grid::CellState::occupied);
  for (int row = 2; row < 398; ++row) {
    for (int col = 2; col < 798; ++col) map->set(col, row, grid::CellState::free);
  }
  // Pillars 0.5 m square every 4 m along two rows.
  for (int k = 1; k < 10; ++k) {
    for (int row_base : {120, 270}) {
      for (int row = row_base; row < row_base + 10; ++row) {
        for (int col = 80 * k; col < 80 * k + 10; ++col) map->set(col, row, grid::CellState::occupied);
      }
    }
  }
  return map;
}

LaserScan simulate(const grid::OccupancyGrid& map, const Pose2& robot) {
  LaserScan scan;
  scan.max_range = 8.0;
  scan.sensor_pose = {0.1, 0.0, 0.0};
  const Pose2 sensor = robot.compose(scan.sensor_pose);
  for (int i = 0; i < 181; ++i) {
    const double bearing = -std::numbers::pi / 2 + std::numbers::pi * i / 180.0;
    scan.bearings.push_back(bearing);
    scan.ranges.push_back(grid::cast_ray(map, sensor.translation(), sensor.yaw + bearing, 8.0,
                                         grid::RayStop::occupied));
  }
  return scan;
}

void run(benchmark::State& state, LaserModelType model, bool pinned_at_5000) {
  const auto map = make_hall();
  AmclParameters parameters;
  parameters.laser_model = model;
  if (pinned_at_5000) parameters.min_particles = parameters.max_particles = 5000;
  AmclFilter filter(parameters, map, 1);
  const Pose2 a{10.0, 10.0, 0.0}, b{10.25, 10.0, 0.0};
  filter.set_pose(a, Eigen::Vector3d(0.01, 0.01, 0.003).asDiagonal());
  const LaserScan scan_a = simulate(*map, a), scan_b = simulate(*map, b);
  filter.update(a, &scan_a);
  bool at_a = true;
  std::size_t particles = 0, updates = 0;
  for (auto _ : state) {
    at_a = !at_a;
    const bool ran = filter.update(at_a ? a : b, at_a ? &scan_a : &scan_b);
    benchmark::DoNotOptimize(ran);
    particles += filter.particles().size();
    ++updates;
  }
  state.counters["particles"] = static_cast<double>(particles) / static_cast<double>(updates);
  state.counters["beams"] = static_cast<double>(parameters.laser_max_beams);
  state.SetLabel(filter.update_count() >= updates ? "every call updated" : "SOME CALLS SKIPPED");
}

void BM_LikelihoodFieldDefaults(benchmark::State& s) { run(s, LaserModelType::likelihood_field, false); }
void BM_LikelihoodField5000(benchmark::State& s) { run(s, LaserModelType::likelihood_field, true); }
void BM_BeamDefaults(benchmark::State& s) { run(s, LaserModelType::beam, false); }
void BM_Beam5000(benchmark::State& s) { run(s, LaserModelType::beam, true); }

void cluster(benchmark::State& state, bool spread) {
  std::mt19937_64 random(7);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<playerkit::amcl::Particle> particles(spread ? 77'000 : 5'000);
  for (auto& p : particles) {
    p.pose = spread ? Pose2{40.0 * uniform(random), 20.0 * uniform(random), std::numbers::pi * (2 * uniform(random) - 1)}
                    : Pose2{10.0 + 0.1 * normal(random), 10.0 + 0.1 * normal(random), 0.05 * normal(random)};
    p.weight = uniform(random);
  }
  playerkit::amcl::PoseClusterer clusterer;
  std::vector<playerkit::amcl::Hypothesis> hypotheses;
  for (auto _ : state) {
    clusterer.cluster(particles, 0.5, 10.0 * std::numbers::pi / 180.0, hypotheses);
    benchmark::DoNotOptimize(hypotheses.data());
  }
  state.counters["clusters"] = static_cast<double>(hypotheses.size());
  state.counters["particles"] = static_cast<double>(particles.size());
}

void BM_ClusterTracked(benchmark::State& s) { cluster(s, false); }
void BM_ClusterSpread(benchmark::State& s) { cluster(s, true); }

BENCHMARK(BM_LikelihoodFieldDefaults)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_LikelihoodField5000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_BeamDefaults)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Beam5000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ClusterTracked)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ClusterSpread)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
