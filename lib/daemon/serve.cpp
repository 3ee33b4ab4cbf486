#include "daemon/serve.hpp"

#include <algorithm>
#include <exception>

#include "config/config_file.hpp"
#include "config/errors.hpp"
#include "core/device_table.hpp"
#include "core/driver_registry.hpp"
#include "core/instantiate.hpp"
#include "core/plugin.hpp"
#include "drivers/builtin.hpp"
#include "drivers/logfile/readlog_driver.hpp"
#include "server/server.hpp"

namespace playerkit::daemon {

namespace {

constexpr int kFailure = 1;
constexpr int kBadConfig = 2;

}  // namespace

core::DriverRegistry load_drivers(const std::vector<std::string>& plugins, core::Logger& logger) {
  core::DriverRegistry registry;
  drivers::register_builtin_drivers(registry);
  for (const std::string& plugin : plugins) {
    core::load_driver_plugin(plugin, registry);
    logger.info("loaded plugin " + plugin);
  }
  return registry;
}

int serve(const ServeOptions& options) {
  core::Logger logger(options.program_name);
  logger.set_level(options.log_level);
  // With -r every header time the server writes is log time: the readlog
  // reader of that file sets log_clock as it replays (logfile-format.md §5).
  core::WallClock wall_clock;
  core::ManualClock log_clock;
  const core::Clock& clock =
      options.readlog ? static_cast<const core::Clock&>(log_clock) : static_cast<const core::Clock&>(wall_clock);

  core::DriverRegistry registry;
  try {
    registry = load_drivers(options.plugins, logger);
  } catch (const core::PluginError& e) {
    logger.error(e.what());
    return kFailure;
  }
  if (options.readlog) {
    // Replaces a plugin's readlog too: -r names what the built-in one replays.
    registry.add(drivers::readlog_driver_spec({.log = *options.readlog,
                                               .speed = options.readlog_speed,
                                               .clock = &log_clock,
                                               .timer = nullptr,
                                               .data_queue = options.readlog_data_queue,
                                               .duration = options.readlog_duration,
                                               .burst = options.readlog_burst}));
  }

  server::ServerOptions server_options;
  server_options.bind_address = options.bind_address;
  server_options.auth_key = options.auth_key;
  core::DeviceTable devices;
  server::Server server(devices, clock, logger, server_options);

  try {
    // With -p 0 the port is only known once bound, and devices outside robot
    // sections are keyed by it: bind first, then read the configuration.
    std::uint16_t default_port = options.port;
    std::vector<std::uint16_t> bound;
    if (options.port == 0) {
      default_port = server.listen(0);
      bound.push_back(default_port);
    }
    const auto load_options = core::load_options_for(registry, default_port);
    const auto config = options.config_text
                            ? config::ConfigFile::parse(*options.config_text, options.config_path, load_options)
                            : config::ConfigFile::load(options.config_path, load_options);
    for (const auto& warning : config.warnings()) logger.warning(warning.to_string());
    core::instantiate_devices(config, registry, devices, clock, logger);
    for (const auto& warning : config.unused_properties()) logger.warning(warning.to_string());
    const auto served = devices.all();
    if (options.readlog && std::none_of(served.begin(), served.end(), [](const core::Device* device) {
          return device->info().driver_name == "readlog";
        })) {
      logger.warning("-r " + *options.readlog + ": no device of " + options.config_path +
                     " has driver \"readlog\"; nothing is replayed");
    }
    if (devices.empty()) {
      logger.error(options.config_path + ": no devices declared, nothing to serve");
      return kBadConfig;
    }
    for (std::uint16_t port : config.ports()) {
      if (port == 0) {
        logger.error(options.config_path + ": a robot section with port 0; only -p 0 picks a free port");
        return kBadConfig;
      }
      if (std::find(bound.begin(), bound.end(), port) == bound.end()) {
        server.listen(port);
        bound.push_back(port);
      }
    }
  } catch (const config::ConfigError& e) {
    logger.error(e.what());
    return kBadConfig;
  } catch (const server::ServerError& e) {
    logger.error(e.what());
    return kFailure;
  }

  try {
    devices.prepare_all();
    devices.start_alwayson();
  } catch (const std::exception& e) {
    logger.error(e.what());
    devices.shutdown_all();
    return kFailure;
  }

  server.stop_on_signals();
  logger.info("serving " + std::to_string(devices.size()) + " devices");
  server.run();
  devices.shutdown_all();
  logger.info("all devices shut down");
  return 0;
}

}  // namespace playerkit::daemon
