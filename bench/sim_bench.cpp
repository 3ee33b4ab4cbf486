// How fast lib/sim runs worlds on one core, no clients attached: simulated
// seconds per wall second for the three goals, and how the cost
// grows with robots and beams ("x realtime" on wall time, as the goals are
// put; "x cpu" on the process's CPU time, which other work on a shared
// machine inflates less). Every robot's devices are active (as if
// subscribed) and every robot wanders: forward until something is close
// ahead or it stalls, then turns.
//
//   sim_bench                 all scenarios
//   sim_bench goals           the three goal worlds only
//   sim_bench growth          robots x beams in the cave
//   sim_bench --seconds 30    simulate longer (default 20 s each, and 1 s of wall time at least)
//   sim_bench --only NAME     only the worlds of this name (one-laser, cave-100, ..., for a profiler)
//   sim_bench --only cave-100 --write-world cave-100.world
//                             write that world's file instead (bench/sim_server_load.sh serves it)
//
// Worlds are Stage 4 world text written here, on data/worlds' bitmaps (found
// through PLAYERKIT_SOURCE_DIR, or the directory given with --worlds).

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <iomanip>
#include <numbers>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "algorithms/grid/distance_map.hpp"
#include "sim/world/noise.hpp"
#include "sim/world/world.hpp"
#include "sim/worldfile/world_loader.hpp"

namespace {

using namespace playerkit;
namespace fs = std::filesystem;

struct Scenario {
  std::string name;
  std::string bitmap;  // in data/worlds
  double width_m = 0.0;
  double height_m = 0.0;
  int robots = 1;
  int laser_beams = 0;   // 0: no laser
  int sonars = 0;        // one-sample sensors in a ring
  double goal = 0.0;     // x real time the issue asks for; 0: none
};

std::string floorplan_text(const Scenario& scenario, const fs::path& worlds) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(4);  // world files have no exponents
  text << "resolution 0.02\ninterval_sim 100\n"
       << "define floorplan model ( color \"gray30\" boundary 1 obstacle_return 1 ranger_return 0.5 )\n"
       << "floorplan ( name \"map\" size [" << scenario.width_m << ' ' << scenario.height_m
       << " 1] pose [0 0 0 0] bitmap \"" << (worlds / scenario.bitmap).string() << "\" )\n";
  return text.str();
}

std::string robot_definition(const Scenario& scenario) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(4);  // world files have no exponents
  if (scenario.laser_beams > 0) {
    text << "define bench_laser ranger ( sensor ( range [0 8.0] fov 180 samples " << scenario.laser_beams
         << " ) )\n";
  }
  if (scenario.sonars > 0) {
    text << "define bench_sonar ranger (\n";
    for (int i = 0; i < scenario.sonars; ++i) {
      const double bearing = 360.0 * i / scenario.sonars;
      const double radius = 0.12;
      text << "  sensor ( range [0 5.0] fov 15 samples 1 pose [" << radius * std::cos(bearing * std::numbers::pi / 180)
           << ' ' << radius * std::sin(bearing * std::numbers::pi / 180) << " 0 " << bearing << "] )\n";
    }
    text << ")\n";
  }
  // A Pioneer-sized base with Stage's pioneer.inc bounds, or a small
  // swarmbot when it only has sonars (Stage's hospital benchmark).
  const bool small = scenario.laser_beams == 0;
  text << "define bench_robot position ( size [" << (small ? "0.25 0.25" : "0.44 0.38")
       << " 0.22] drive \"diff\" localization \"odom\" odom_error [0.01 0.01 0 0.01]"
       << " velocity_bounds [-0.5 0.5 0 0 0 0 -90 90]";
  if (scenario.laser_beams > 0) text << " bench_laser ( pose [0 0 0 0] )";
  if (scenario.sonars > 0) text << " bench_sonar ( pose [0 0 0 0] )";
  text << " )\n";
  return text.str();
}

// Free poses at least `clearance` from walls and `spacing` from each other,
// drawn from the seed.
std::vector<geometry::Pose2> free_poses(const grid::OccupancyGrid& map, int count, double clearance,
                                        double spacing) {
  const grid::DistanceMap distances(map, clearance + 0.1);
  sim::NoiseDraws draws(1, 0, 0);
  std::vector<geometry::Pose2> poses;
  const Eigen::Vector2d low = map.origin();
  const Eigen::Vector2d size{map.width() * map.resolution(), map.height() * map.resolution()};
  for (int attempt = 0; attempt < 2'000'000 && static_cast<int>(poses.size()) < count; ++attempt) {
    const Eigen::Vector2d point{low.x() + draws.uniform() * size.x(), low.y() + draws.uniform() * size.y()};
    const double yaw = draws.uniform(-std::numbers::pi, std::numbers::pi);
    if (map.state_at_world(point) == grid::CellState::occupied || distances.at_world(point) < clearance) continue;
    const bool crowded = std::any_of(poses.begin(), poses.end(), [&](const geometry::Pose2& other) {
      return (other.translation() - point).norm() < spacing;
    });
    if (!crowded) poses.push_back({point.x(), point.y(), yaw});
  }
  if (static_cast<int>(poses.size()) < count) {
    std::fprintf(stderr, "sim_bench: only %zu free places for %d robots\n", poses.size(), count);
    std::exit(1);
  }
  return poses;
}

// The scenario's world file: the floorplan, then its robots on free poses.
std::string world_text(const Scenario& scenario, const fs::path& worlds) {
  using namespace sim::worldfile;
  const std::string floorplan = floorplan_text(scenario, worlds);
  const auto empty = describe_world_text(floorplan, scenario.name + ".world", worlds);
  const double radius = scenario.laser_beams > 0 ? 0.3 : 0.18;
  const auto poses = free_poses(empty.map, scenario.robots, radius + 0.1, 2.5 * radius);
  std::ostringstream text;
  text << std::fixed << std::setprecision(4);  // world files have no exponents
  text << floorplan << robot_definition(scenario);
  for (int i = 0; i < scenario.robots; ++i) {
    const auto& pose = poses[static_cast<std::size_t>(i)];
    text << "bench_robot ( name \"r" << i << "\" pose [" << pose.x << ' ' << pose.y << " 0 "
         << pose.yaw * 180.0 / std::numbers::pi << "] )\n";
  }
  return text.str();
}

sim::worldfile::LoadedWorld build_world(const Scenario& scenario, const fs::path& worlds) {
  return sim::worldfile::load_world_text(world_text(scenario, worlds), scenario.name + ".world", worlds, {.seed = 7});
}

struct Robot {
  sim::ModelId base = sim::kNoModel;
  sim::ModelId ranger = sim::kNoModel;
  bool laser = false;
};

// Forward until within 0.6 m of something ahead or stalled, then turn.
void wander(sim::World& world, const Robot& robot) {
  double nearest_ahead = 8.0;
  if (robot.laser) {
    const auto& ranges = world.laser(robot.ranger).ranges;
    const std::size_t n = ranges.size();
    for (std::size_t i = n / 3; i < n - n / 3; ++i) nearest_ahead = std::min(nearest_ahead, ranges[i]);
  } else if (robot.ranger != sim::kNoModel) {
    const auto& ranges = world.sonar(robot.ranger).ranges;
    if (!ranges.empty()) nearest_ahead = std::min({ranges.front(), ranges[1 % ranges.size()], ranges.back()});
  }
  const bool blocked = world.position(robot.base).stalled || nearest_ahead < 0.6;
  world.command_velocity(robot.base, blocked ? Eigen::Vector3d{0.0, 0.0, 1.0} : Eigen::Vector3d{0.4, 0.0, 0.0});
}

struct Figures {
  double load_s = 0.0;
  double speedup = 0.0;
  double step_us = 0.0;
  double cpu_speedup = 0.0;  // on this process's CPU time: what a shared machine's other work does not inflate
};

double process_cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + static_cast<double>(now.tv_nsec) * 1e-9;
}

Figures run(const Scenario& scenario, const fs::path& worlds, double sim_seconds) {
  const auto load_start = std::chrono::steady_clock::now();
  auto loaded = build_world(scenario, worlds);
  const double load_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - load_start).count();
  sim::World& world = loaded.world;
  std::vector<Robot> robots;
  for (const auto& device : loaded.devices) {
    world.set_active(device.model, true);
    const auto& spec = world.spec(device.model);
    if (std::holds_alternative<sim::PositionSpec>(spec.params)) robots.push_back({device.model});
  }
  for (auto& robot : robots) {
    for (const sim::ModelId child : world.children(robot.base)) {
      const auto& params = world.spec(child).params;
      if (std::holds_alternative<sim::LaserSpec>(params)) robot = {robot.base, child, true};
      if (std::holds_alternative<sim::SonarSpec>(params)) robot = {robot.base, child, false};
    }
  }
  // At least `sim_seconds`, and at least a wall second so that fast worlds
  // are timed over enough steps.
  const double cpu_start = process_cpu_seconds();
  const auto start = std::chrono::steady_clock::now();
  const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  std::uint64_t steps = 0;
  while ((world.time() < sim_seconds || elapsed() < 1.0) && steps < 1'000'000) {
    for (const auto& robot : robots) wander(world, robot);
    world.step();
    ++steps;
  }
  const double wall = elapsed();
  const double cpu = process_cpu_seconds() - cpu_start;
  return {load_s, world.time() / wall, wall / static_cast<double>(steps) * 1e6, world.time() / cpu};
}

void print_header() {
  std::printf("%-16s %7s %6s %7s %9s %12s %11s %9s %8s\n", "world", "robots", "beams", "sonars", "load s",
              "step us", "x realtime", "x cpu", "goal");
}

void print_row(const Scenario& scenario, const Figures& figures) {
  std::printf("%-16s %7d %6d %7d %9.2f %12.1f %11.1f %9.1f", scenario.name.c_str(), scenario.robots,
              scenario.laser_beams, scenario.sonars, figures.load_s, figures.step_us, figures.speedup,
              figures.cpu_speedup);
  if (scenario.goal > 0) {
    std::printf(" %7.0fx %s", scenario.goal, figures.speedup >= scenario.goal ? "met" : "MISSED");
  }
  std::printf("\n");
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  fs::path worlds = fs::path(PLAYERKIT_SOURCE_DIR) / "data" / "worlds";
  double sim_seconds = 20.0;
  bool goals = true;
  bool growth = true;
  std::string only;
  std::string write_world;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--seconds" && i + 1 < argc) {
      sim_seconds = std::atof(argv[++i]);
    } else if (arg == "--only" && i + 1 < argc) {
      only = argv[++i];
    } else if (arg == "--write-world" && i + 1 < argc) {
      write_world = argv[++i];
    } else if (arg == "--worlds" && i + 1 < argc) {
      worlds = argv[++i];
    } else if (arg == "goals") {
      growth = false;
    } else if (arg == "growth") {
      goals = false;
    } else {
      std::fprintf(stderr,
                   "usage: sim_bench [goals|growth] [--seconds S] [--only WORLD] [--worlds DIR]\n"
                   "       sim_bench --only WORLD --write-world FILE\n");
      return 2;
    }
  }
  bool written = false;
  if (write_world.empty()) print_header();
  const auto measure = [&](const Scenario& scenario) {
    if (!only.empty() && scenario.name != only) return;
    if (write_world.empty()) {
      print_row(scenario, run(scenario, worlds, sim_seconds));
    } else if (!written) {
      std::ofstream(write_world) << world_text(scenario, worlds);
      written = true;
    }
  };
  if (goals) {
    const std::vector<Scenario> targets{
        {"one-laser", "stage-cave.png", 16, 16, 1, 361, 0, 5000},
        {"cave-100", "stage-cave.png", 32, 32, 100, 180, 0, 50},
        {"hospital-1000", "stage-hospital_section.png", 140, 60, 1000, 0, 12, 10},
    };
    for (const auto& scenario : targets) measure(scenario);
  }
  if (growth) {
    for (const int robots : {1, 10, 100}) {
      for (const int beams : {45, 180, 361}) {
        const Scenario scenario{"cave-growth", "stage-cave.png", 32, 32, robots, beams, 0, 0};
        measure(scenario);
      }
    }
    for (const int robots : {10, 100, 1000}) {
      const Scenario scenario{"hospital-growth", "stage-hospital_section.png", 140, 60, robots, 0, 12, 0};
      measure(scenario);
    }
  }
  if (!write_world.empty() && !written) {
    std::fprintf(stderr, "sim_bench: --write-world needs --only with a scenario's name\n");
    return 2;
  }
  return 0;
}
