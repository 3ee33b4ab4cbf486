#include "emulate_session.hpp"

#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <thread>

#include "emulators/runner/fault_injector.hpp"
#include "links/link_error.hpp"
#include "map/map_file.hpp"

namespace playerkit::player_drivers {

namespace {

using Clock = std::chrono::steady_clock;

std::string stats_line(emulators::EmulatorRig& rig, std::size_t index) {
  const auto stats = rig.runner(index).stats();
  std::string line = "stats " + rig.kind(index).name + " " + rig.runner(index).device_path() + ": in " +
                     std::to_string(stats.bytes_in) + " B, out " + std::to_string(stats.bytes_out) + " B, " +
                     std::to_string(stats.telegrams_out) + " telegrams, host opened " +
                     std::to_string(stats.host_connects) + "x, closed " + std::to_string(stats.host_disconnects) + "x";
  const std::string faults = emulators::describe(stats.faults);
  if (!faults.empty()) line += ", faults: " + faults;
  return line + "; " + rig.describe(index);
}

}  // namespace

std::shared_ptr<const grid::OccupancyGrid> load_emulator_map(const EmulateOptions& options, std::string& how) {
  const std::filesystem::path& file = *options.map;
  const std::string extension = file.extension().string();
  if (extension == ".yaml" || extension == ".yml") {
    how = file.string() + " (ROS map description)";
    return std::make_shared<const grid::OccupancyGrid>(map::load_map(file));
  }
  if (options.map_scale) {
    how = file.string() + " at " + std::to_string(*options.map_scale) + " m/pixel";
    return std::make_shared<const grid::OccupancyGrid>(
        map::load_map(file, {.resolution = options.map_scale, .negate = options.map_negate}));
  }
  std::filesystem::path beside = file;
  beside.replace_extension(".yaml");
  if (std::filesystem::exists(beside)) {
    how = file.string() + " through " + beside.string();
    return std::make_shared<const grid::OccupancyGrid>(map::load_map(beside));
  }
  throw UsageError("--map " + file.string() + " is an image: give its scale with --map-scale METRES_PER_PIXEL (or put " +
                   beside.filename().string() + " beside it)");
}

int run_emulators(const EmulateOptions& options, const emulators::EmulatorCatalog& catalog, std::ostream& out,
                  std::ostream& err, const std::function<bool()>& stop_requested) {
  std::shared_ptr<const grid::OccupancyGrid> map;
  if (options.map) {
    std::string how;
    try {
      map = load_emulator_map(options, how);
    } catch (const UsageError& e) {
      err << "player-drivers: emulate: " << e.what() << "\n" << std::flush;
      return kExitUsage;
    } catch (const std::exception& e) {
      err << "player-drivers: emulate: " << e.what() << "\n" << std::flush;
      return kExitFailure;
    }
    char size[96];
    std::snprintf(size, sizeof size, "%d x %d cells of %.3f m", map->width(), map->height(), map->resolution());
    err << "player-drivers: map " << how << ": " << size << "\n" << std::flush;
  }

  std::unique_ptr<emulators::EmulatorRig> rig;
  try {
    rig = std::make_unique<emulators::EmulatorRig>(catalog, options.requests,
                                                   emulators::RigSettings{.map = map, .faults = options.faults});
  } catch (const std::invalid_argument& e) {
    err << "player-drivers: emulate: " << e.what() << "\n" << std::flush;
    return kExitUsage;
  } catch (const links::LinkError& e) {
    err << "player-drivers: emulate: " << e.what() << "\n" << std::flush;
    return kExitFailure;
  }

  for (std::size_t i = 0; i < rig->size(); ++i) {
    out << rig->kind(i).name << " on " << rig->runner(i).device_path() << ": " << rig->config_line(i) << "\n";
  }
  out << std::flush;
  if (options.faults.any()) err << "player-drivers: faults on every line: " << options.faults.describe() << "\n";
  for (std::size_t i = 0; i < rig->size(); ++i) {
    if (rig->carried(i)) {
      err << "player-drivers: " << rig->kind(i).name << " rides on the emulated robot (its mount option)\n";
    }
  }
  err << std::flush;

  const auto start = Clock::now();
  auto next_stats = start + std::chrono::seconds(1);
  while (!stop_requested()) {
    const auto now = Clock::now();
    // Stats that are due go out even when the duration ends at the same look.
    if (options.stats && now >= next_stats) {
      next_stats += std::chrono::seconds(1);
      for (std::size_t i = 0; i < rig->size(); ++i) err << stats_line(*rig, i) << "\n";
      err << std::flush;
    }
    if (options.duration && now - start >= std::chrono::duration<double>(*options.duration)) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return kExitOk;
}

}  // namespace playerkit::player_drivers
