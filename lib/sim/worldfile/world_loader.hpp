#pragma once
// Stage world files read into a simulated world (stage-worlds.md): the
// dialect is picked from what the file contains (§1.9), Stage 1.3 (Player
// 1.5's `player -s` worlds: ports, devices nested in robots, bitmap
// entities) or Stage 3/4 (floorplan models with stretched bitmaps, ranger
// with sensors); the map becomes an occupancy grid, models become
// sim::ModelSpecs, and every device a Player client can open is listed.
//
//   const auto loaded = worldfile::load_world("data/worlds/simple.world", {.default_port = 6665});
//   for (const auto& warning : loaded.warnings) std::cerr << warning << '\n';
//   for (const auto& device : loaded.devices) ...   // port, interface code, index, model

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "algorithms/grid/occupancy_grid.hpp"
#include "sim/world/model_spec.hpp"
#include "sim/world/world.hpp"
#include "sim/worldfile/worldfile_error.hpp"

namespace playerkit::sim::worldfile {

struct WorldLoadOptions {
  std::uint64_t seed = 0;
  // Stage 1.3 robots without a `port`, and every device of a Stage 3/4
  // world (which has no ports).
  std::uint16_t default_port = 6665;
};

// One Player device the world offers.
struct SimDevice {
  std::uint16_t port = 0;
  std::uint16_t interface_code = 0;  // protocol/interfaces.hpp
  std::uint16_t index = 0;
  ModelId model = kNoModel;
  std::string driver_name;  // the world file's type word: "position", "lbd", "ranger"
};

enum class Dialect { stage13, stage3, stage4 };
// "Stage 1.3", "Stage 3", "Stage 4".
std::string_view dialect_name(Dialect dialect);

// A world before it is made: what load_world adds to sim::World, in order.
// models[i].parent and devices[j].model index `models`.
struct WorldDescription {
  WorldSettings settings;
  grid::OccupancyGrid map;
  std::vector<ModelSpec> models;
  std::vector<SimDevice> devices;  // in world order: robot by robot for Stage 3/4
  std::vector<std::string> warnings;  // "file:line:col: message"
  Dialect dialect = Dialect::stage4;
};

struct LoadedWorld {
  World world;
  std::vector<SimDevice> devices;  // model: the World's ids
  std::vector<std::string> warnings;
  Dialect dialect = Dialect::stage4;
};

// Throws WorldFileError ("file:line:col: message"): syntax, an unknown
// model type, a malformed value, an unreadable bitmap, a device address
// given twice.
WorldDescription describe_world(const std::filesystem::path& file, const WorldLoadOptions& options = {});
// The same for text in memory named `name`; includes and bitmaps are found
// in `directory`.
WorldDescription describe_world_text(std::string_view text, const std::string& name,
                                     const std::filesystem::path& directory, const WorldLoadOptions& options = {});

// The description added to a sim::World.
LoadedWorld make_world(WorldDescription description);
LoadedWorld load_world(const std::filesystem::path& file, const WorldLoadOptions& options = {});
LoadedWorld load_world_text(std::string_view text, const std::string& name, const std::filesystem::path& directory,
                            const WorldLoadOptions& options = {});

}  // namespace playerkit::sim::worldfile
