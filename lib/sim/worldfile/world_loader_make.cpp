#include "sim/worldfile/world_loader.hpp"

namespace playerkit::sim::worldfile {

LoadedWorld make_world(WorldDescription description) {
  LoadedWorld loaded{World(description.settings, std::move(description.map)), {}, std::move(description.warnings),
                     description.dialect};
  std::vector<ModelId> ids;
  ids.reserve(description.models.size());
  for (ModelSpec& spec : description.models) {
    if (spec.parent != kNoModel) spec.parent = ids.at(static_cast<std::size_t>(spec.parent));
    ids.push_back(loaded.world.add(std::move(spec)));
  }
  loaded.devices = std::move(description.devices);
  for (SimDevice& device : loaded.devices) device.model = ids.at(static_cast<std::size_t>(device.model));
  return loaded;
}

LoadedWorld load_world(const std::filesystem::path& file, const WorldLoadOptions& options) {
  return make_world(describe_world(file, options));
}

LoadedWorld load_world_text(std::string_view text, const std::string& name, const std::filesystem::path& directory,
                            const WorldLoadOptions& options) {
  return make_world(describe_world_text(text, name, directory, options));
}

}  // namespace playerkit::sim::worldfile
