#include "daemon/simulation.hpp"

#include <optional>
#include <sstream>
#include <utility>

#include "core/instantiate.hpp"
#include "drivers/sim/sim_drivers.hpp"
#include "drivers/sim/world_configuration.hpp"
#include "drivers/sim/simulation_source.hpp"
#include "sim/worldfile/world_loader.hpp"
#include "text/printable.hpp"

namespace playerkit::daemon {

ServedWorld load_served_world(const SimulationOptions& options, std::uint16_t default_port) {
  auto loaded = sim::worldfile::load_world(options.world, {.seed = options.seed, .default_port = default_port});
  ServedWorld served;
  served.warnings = std::move(loaded.warnings);
  served.devices = drivers::sim::world_configuration(loaded.world, loaded.devices, default_port);
  std::ostringstream summary;
  summary << text::excerpt(options.world) << " (" << sim::worldfile::dialect_name(loaded.dialect)
          << "): " << loaded.devices.size() << (loaded.devices.size() == 1 ? " device" : " devices") << ", step "
          << loaded.world.settings().step << " s, ";
  if (options.speedup > 0.0) {
    summary << options.speedup << "x real time";
  } else {
    summary << "as fast as possible";
  }
  if (options.sim_time) summary << ", stopping at " << *options.sim_time << " s";
  if (options.paused) summary << ", paused";
  std::optional<drivers::sim::PictureSettings> picture;
  if (!options.picture.empty()) {
    picture = drivers::sim::PictureSettings{.file = options.picture,
                                            .inputs = {options.picture_inputs.begin(), options.picture_inputs.end()}};
    summary << ", picture " << text::excerpt(options.picture);
  }
  served.summary = summary.str();
  served.source = std::make_shared<drivers::sim::SimulationSource>(
      std::move(loaded.world), options.world,
      drivers::sim::SimulationSettings{.speedup = options.speedup,
                                       .run_limit = options.sim_time,
                                       .start_paused = options.paused,
                                       .start_from_prepare_only = true,
                                       .picture = std::move(picture)});
  return served;
}

void register_world_drivers(core::DriverRegistry& registry, const ServedWorld& world) {
  for (core::DriverSpec& spec : drivers::simulation_driver_specs(world.source)) {
    spec.family = "sim";
    registry.add(std::move(spec));
  }
}

config::ConfigFile world_device_configuration(const ServedWorld& world, const core::DriverRegistry& registry,
                                              std::uint16_t default_port) {
  return config::ConfigFile::parse(world.devices, world.source->world_name() + " (devices)",
                                   core::load_options_for(registry, default_port));
}

}  // namespace playerkit::daemon
