#pragma once
// Internal: what the dialect readers fill in while walking the entity tree.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <map>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "sim/world/model_spec.hpp"
#include "sim/worldfile/world_loader.hpp"
#include "sim/worldfile/world_loader_map.hpp"
#include "sim/worldfile/world_loader_properties.hpp"
#include "sim/worldfile/worldfile_tree.hpp"

namespace playerkit::sim::worldfile {

// A model a Player client can open, before its index is chosen.
struct DeviceEntity {
  int model = -1;  // index in LoadContext::models
  std::uint16_t interface_code = 0;
  std::string driver_name;
  int robot = -1;          // Stage 3/4: the robot (top-level position model) it rides on, in world order
  std::uint16_t port = 0;  // Stage 1.3: the robot's or its own port, 0 for the default
  std::optional<int> index;  // Stage 1.3: an explicit `index`
  SourceLocation where;
};

struct LoadContext {
  const WorldTree& tree;
  Units units;
  std::filesystem::path directory;  // of the top-level file: bitmaps are found from here
  WorldLoadOptions options;
  std::vector<std::string>& warnings;
  Dialect dialect = Dialect::stage4;

  WorldSettings settings;
  std::vector<ModelSpec> models;  // parent: an index in this vector
  std::vector<DeviceEntity> devices;
  MapPlan map;
  std::set<std::string, std::less<>> names;  // given so far
  std::map<std::pair<int, std::string>, int> siblings;  // (parent, type) -> models so far

  int add_model(ModelSpec spec) {
    models.push_back(std::move(spec));
    return static_cast<int>(models.size()) - 1;
  }

  // A model's name as Stage 4 gives it (§2.1): `given` at top level,
  // "<parent>.<given>" for a child unless `given` starts with '/' (then the
  // rest), and without `given` "<type>:<n>" (under the parent's name for a
  // child), n counting earlier siblings of the type. A name already taken
  // becomes (with a warning) "name#2", "name#3"...: sim::World wants unique
  // names, and Stage's lookups found only the last of equal names anyway.
  std::string model_name(const std::string& given, const std::string& type, int parent, const SourceLocation& where);

  // The error for an entity type that is neither a model type of the
  // dialect nor a macro: "unknown macro or model type "pioneer2x" (did you
  // mean "pioneer2dx"?)", or "macro "x" is used before its definition at ...".
  [[noreturn]] void unknown_type(const Entity& entity, std::span<const std::string_view> known_types) const;
};

// A file named in the world: absolute as written, else from the directory
// of the top-level world file (Stage reads bitmaps from there).
inline std::filesystem::path world_relative(const std::filesystem::path& directory, const std::string& name) {
  if (!name.empty() && name.front() == '/') return name;
  return directory / name;
}

// Stage 1.3: fills settings, models, devices, map.
void read_stage13_world(LoadContext& context);
// Stage 3 and 4.
void read_stage4_world(LoadContext& context);

// The colour a `color` property names: x11_color, "random" (Stage 4: drawn
// from the seed), or red with a warning for an unknown name, as Stage does.
Rgb color_named(const Value& name, LoadContext& context);

}  // namespace playerkit::sim::worldfile
