#include "daemon/check.hpp"

#include "config/errors.hpp"
#include "core/server_clock.hpp"
#include "core/instantiate.hpp"
#include "drivers/logfile/readlog_driver.hpp"
#include "drivers/logfile/replay_session.hpp"

namespace playerkit::daemon {

void check_replay_log(const std::string& path) { (void)drivers::first_replay_time(path); }

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
  const auto load_options = core::load_options_for(registry, options.port);
  CheckedConfiguration checked{
      options.config_text ? config::ConfigFile::parse(*options.config_text, options.config_path, load_options)
                          : config::ConfigFile::load(options.config_path, load_options),
      {}};
  for (const auto& warning : checked.config.warnings()) checked.warnings.push_back(warning.to_string());
  core::ServerClock clock;
  core::DeviceTable devices;
  core::instantiate_devices(checked.config, registry, devices, clock, logger);
  core::check_devices(checked.config, devices);
  check_served(devices, options.config_path);
  for (const auto& warning : checked.config.unused_properties()) checked.warnings.push_back(warning.to_string());
  return checked;
}

}  // namespace playerkit::daemon
