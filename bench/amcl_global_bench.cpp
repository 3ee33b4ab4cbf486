// Global localization on a large simulated office floor (issue 34): for a
// floor seed, a route seed and filter seeds, where the filter first held the
// robot for good (the step, the time and the distance travelled), the second
// half's position RMSE, and the wall time against the log's time.
//   amcl_global_bench [resolution_m] [floor_seed] [route_seeds] [filter_seeds] [legs] [size_m]
// AMCL_GLOBAL_BENCH_SET=name=value,... changes parameters (seed_search_position_step=0
// is Player 1.5's uniform start); AMCL_GLOBAL_BENCH_TRACK=1 starts at the true
// pose instead; AMCL_GLOBAL_BENCH_PGM=FILE writes the floor. The log's time
// is 10 scans a second at 1 m/s. Reports go in docs/amcl.md.

#include "algorithms/amcl/amcl_filter.hpp"
#include "algorithms/amcl/large_office_test_support.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

using namespace playerkit;

struct Outcome {
  std::size_t converged_step = 0;  // first step from which every estimate is within 1 m
  bool converged = false;
  double converged_distance = 0.0;
  double second_half_rmse = 0.0;
  double second_half_max = 0.0;
  double wall_seconds = 0.0;
  double first_update_seconds = 0.0;  // the likelihood field is built, and the seed search runs, in it
  std::size_t particles = 0;
};

// The defaults, but for name=value pairs in AMCL_GLOBAL_BENCH_SET (comma separated) for trying others.
amcl::AmclParameters bench_parameters() {
  amcl::AmclParameters parameters;
  const char* set = std::getenv("AMCL_GLOBAL_BENCH_SET");
  std::string rest = set != nullptr ? set : "";
  while (!rest.empty()) {
    const std::size_t comma = rest.find(',');
    const std::string item = rest.substr(0, comma);
    rest = comma == std::string::npos ? "" : rest.substr(comma + 1);
    const std::size_t equals = item.find('=');
    if (equals == std::string::npos) continue;
    const std::string name = item.substr(0, equals);
    const double value = std::atof(item.c_str() + equals + 1);
    if (name == "seed_search_position_step") parameters.seed_search_position_step = value;
    else if (name == "seed_search_heading_step_deg") parameters.seed_search_heading_step = value * 3.14159265358979 / 180;
    else if (name == "seed_search_candidates") parameters.seed_search_candidates = static_cast<std::size_t>(value);
    else if (name == "seed_search_distance") parameters.seed_search_distance = value;
    else if (name == "seed_search_pool_factor") parameters.seed_search_pool_factor = static_cast<std::size_t>(value);
    else if (name == "seed_search_uniform_share") parameters.seed_search_uniform_share = value;
    else if (name == "seed_search_below_density") parameters.seed_search_below_density = value;
    else if (name == "global_particles_most") parameters.global_particles_most = static_cast<std::size_t>(value);
    else if (name == "search_end_updates") parameters.search_end_updates = static_cast<std::size_t>(value);
    else std::fprintf(stderr, "unknown parameter %s\n", name.c_str());
  }
  return parameters;
}

Outcome run(const amcl::test::LargeOffice& office, const std::vector<amcl::test::LoggedStep>& log,
            std::uint64_t filter_seed) {
  const auto started = std::chrono::steady_clock::now();
  amcl::AmclFilter filter(bench_parameters(), office.map, filter_seed);
  if (std::getenv("AMCL_GLOBAL_BENCH_TRACK") != nullptr) {
    filter.set_pose(log.front().truth, Eigen::Vector3d(0.01, 0.01, 0.005).asDiagonal());
  }
  Outcome outcome;
  std::vector<double> errors;
  errors.reserve(log.size());
  for (const auto& step : log) {
    const auto before = std::chrono::steady_clock::now();
    filter.update(step.odometry, &step.scan);
    if (&step == &log.front()) {
      outcome.first_update_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - before).count();
    }
    const auto estimate = filter.predict(step.odometry);
    errors.push_back(std::hypot(estimate.mean.x - step.truth.x, estimate.mean.y - step.truth.y));
  }
  outcome.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  outcome.particles = filter.global_particles();
  std::size_t from = errors.size();
  while (from > 0 && errors[from - 1] <= 1.0) --from;
  outcome.converged = from < errors.size();
  outcome.converged_step = from;
  for (std::size_t i = 1; i <= from && i < log.size(); ++i) {
    outcome.converged_distance += std::hypot(log[i].truth.x - log[i - 1].truth.x, log[i].truth.y - log[i - 1].truth.y);
  }
  double sum = 0.0;
  const std::size_t half = errors.size() / 2;
  for (std::size_t i = half; i < errors.size(); ++i) {
    sum += errors[i] * errors[i];
    outcome.second_half_max = std::max(outcome.second_half_max, errors[i]);
  }
  outcome.second_half_rmse = std::sqrt(sum / static_cast<double>(errors.size() - half));
  return outcome;
}

}  // namespace

int main(int argc, char** argv) {
  const auto arg = [&](int i, double fallback) { return argc > i ? std::atof(argv[i]) : fallback; };
  amcl::test::LargeOfficeSpec floor;
  floor.resolution = arg(1, 0.05);
  const auto floor_seed = static_cast<std::uint64_t>(arg(2, 1));
  const int route_seeds = static_cast<int>(arg(3, 3));
  const int filter_seeds = static_cast<int>(arg(4, 2));
  amcl::test::OfficeDriveSpec drive;
  drive.legs = static_cast<std::size_t>(arg(5, 8));
  floor.width = floor.height = arg(6, 150.0);

  auto started = std::chrono::steady_clock::now();
  const auto office = amcl::test::make_large_office(floor_seed, floor);
  std::printf("floor %g x %g m at %g m: %d x %d cells, %.0f m^2 free, built in %.2f s\n", floor.width,
              floor.height, floor.resolution, office.map->width(), office.map->height(), office.free_area,
              std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count());
  if (const char* path = std::getenv("AMCL_GLOBAL_BENCH_PGM")) {  // to look at the floor
    if (std::FILE* out = std::fopen(path, "wb")) {
      std::fprintf(out, "P5 %d %d 255\n", office.map->width(), office.map->height());
      for (int row = office.map->height() - 1; row >= 0; --row) {
        for (int col = 0; col < office.map->width(); ++col) {
          const auto cell = office.map->at(col, row);
          std::fputc(cell == grid::CellState::free ? 255 : cell == grid::CellState::occupied ? 0 : 128, out);
        }
      }
      std::fclose(out);
    }
  }
  std::printf("route filter steps log_s particles converged_step converged_s converged_m half_rmse_m half_max_m first_update_s wall_s realtime\n");
  for (int route = 1; route <= route_seeds; ++route) {
    const auto log = amcl::test::drive_large_office(office, static_cast<std::uint64_t>(route), drive);
    const double log_seconds = 0.1 * static_cast<double>(log.size());
    for (int seed = 1; seed <= filter_seeds; ++seed) {
      const Outcome o = run(office, log, static_cast<std::uint64_t>(seed));
      std::printf("%d %d %zu %.1f %zu %s %.1f %.1f %.3f %.3f %.2f %.2f %.0fx\n", route, seed, log.size(), log_seconds,
                  o.particles, o.converged ? std::to_string(o.converged_step).c_str() : "never",
                  0.1 * static_cast<double>(o.converged_step), o.converged_distance, o.second_half_rmse,
                  o.second_half_max, o.first_update_seconds, o.wall_seconds, log_seconds / o.wall_seconds);
      std::fflush(stdout);
    }
  }
  return 0;
}
