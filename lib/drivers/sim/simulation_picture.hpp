#pragma once
// A picture of a served world (lib/sim/render) for `player-serve -s WORLD
// --picture FILE.png`: the robots' trails recorded after every step, and the
// PNG written on request and when the simulation ends. The SimulationHost
// owns one when asked for it, and calls record() and snapshot() with the
// world locked; drawing and writing happen unlocked, so the world keeps
// stepping meanwhile.

#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

#include "sim/render/trails.hpp"
#include "sim/render/world_picture.hpp"
#include "sim/render/world_snapshot.hpp"
#include "sim/world/world.hpp"

namespace playerkit::drivers::sim {

struct PictureSettings {
  std::filesystem::path file;                     // written as PNG whatever its name
  std::vector<std::filesystem::path> inputs;      // never written over (the world file, the configuration)
  playerkit::sim::render::PictureOptions options{};
  playerkit::sim::render::TrailOptions trails{};
};

class SimulationPicture {
 public:
  explicit SimulationPicture(PictureSettings settings);

  // With the world locked: after every step (and once at the start).
  void record(const playerkit::sim::World& world);
  [[nodiscard]] playerkit::sim::render::WorldSnapshot snapshot(const playerkit::sim::World& world) const;
  // Unlocked: draws and writes the PNG, atomically (lib/files). Throws
  // files::OutputIsInputError, files::OutputError.
  void write(const playerkit::sim::render::WorldSnapshot& snapshot);

  [[nodiscard]] const PictureSettings& settings() const { return settings_; }

 private:
  const PictureSettings settings_;
  playerkit::sim::render::Trails trails_;  // under the host's world lock
  std::mutex write_mutex_;                 // one write at a time
};

}  // namespace playerkit::drivers::sim
