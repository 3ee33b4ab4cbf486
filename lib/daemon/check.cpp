#include "daemon/check.hpp"

#include "config/errors.hpp"
#include "core/server_clock.hpp"
#include "daemon/simulation.hpp"
#include "protocol/messages/player.hpp"
#include "core/instantiate.hpp"
#include "drivers/logfile/readlog_driver.hpp"
#include "drivers/logfile/replay_session.hpp"

namespace playerkit::daemon {

void check_replay_log(const std::string& path) { (void)drivers::first_replay_time(path); }

std::vector<std::string> device_list_warnings(const core::DeviceTable& devices) {
  const std::size_t capacity = protocol::DeviceList{}.devices.size();
  std::vector<std::string> warnings;
  for (const std::uint16_t port : devices.ports()) {
    const std::size_t served = devices.on_port(port).size();
    if (served <= capacity) continue;
    warnings.push_back("port " + std::to_string(port) + " serves " + std::to_string(served) +
                       " devices; Player 1.5's device list holds " + std::to_string(capacity) +
                       ": clients listing devices see the first " + std::to_string(capacity) +
                       ", and every device can still be opened by its address");
  }
  return warnings;
}

void check_served(const core::DeviceTable& devices, const std::string& config_path) {
  if (devices.empty()) {
    throw config::ConfigError(config::SourceLocation{config_path}, "no devices declared, nothing to serve");
  }
}

core::DriverSpec replay_driver_spec(const ServeOptions& options) {
  return drivers::readlog_driver_spec({.log = *options.readlog,
                                       .speed = options.readlog_speed,
                                       .timer = nullptr,
                                       .data_queue = options.readlog_data_queue,
                                       .duration = options.readlog_duration,
                                       .burst = options.readlog_burst});
}

CheckedConfiguration check_configuration(const ServeOptions& options) {
  core::Logger logger(options.program_name);
  logger.set_level(core::LogLevel::kError);
  core::DriverRegistry registry = load_drivers(options.plugins, logger);
  if (options.readlog) {
    check_replay_log(*options.readlog);
    registry.add(replay_driver_spec(options));
  }
  CheckedConfiguration checked;
  core::ServerClock clock;
  core::DeviceTable devices;
  if (options.simulation) {
    ServedWorld world = load_served_world(*options.simulation, options.port);
    checked.warnings = std::move(world.warnings);
    register_world_drivers(registry, world);
    checked.configs.push_back(world_device_configuration(world, registry, options.port));
  }
  if (options.has_configuration()) {
    const auto load_options = core::load_options_for(registry, options.port);
    checked.configs.push_back(options.config_text
                                  ? config::ConfigFile::parse(*options.config_text, options.config_path, load_options)
                                  : config::ConfigFile::load(options.config_path, load_options));
  }
  for (const auto& config : checked.configs) {
    for (const auto& warning : config.warnings()) checked.warnings.push_back(warning.to_string());
  }
  for (const auto& config : checked.configs) core::instantiate_devices(config, registry, devices, clock, logger);
  for (const auto& config : checked.configs) core::check_devices(config, devices);
  check_served(devices, options.served_name());
  for (const auto& config : checked.configs) {
    for (const auto& warning : config.unused_properties()) checked.warnings.push_back(warning.to_string());
  }
  for (std::string& warning : device_list_warnings(devices)) checked.warnings.push_back(std::move(warning));
  return checked;
}

}  // namespace playerkit::daemon
