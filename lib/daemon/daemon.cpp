#include "daemon/daemon.hpp"

#include <algorithm>
#include <exception>
#include <stdexcept>

#include "config/config_file.hpp"
#include "config/errors.hpp"
#include "core/instantiate.hpp"
#include "core/plugin.hpp"
#include "daemon/check.hpp"
#include "daemon/simulation.hpp"
#include "sim/worldfile/worldfile_error.hpp"
#include "text/printable.hpp"
#include "server/server.hpp"

namespace playerkit::daemon {

Daemon::Daemon(ServeOptions options) : options_(std::move(options)), logger_(options_.program_name) {
  logger_.set_level(options_.log_level);
  try {
    registry_ = load_drivers(options_.plugins, logger_);
    for (const auto& spec : options_.extra_drivers) registry_.add(spec);
  } catch (const core::PluginError& e) {
    logger_.error(e.what());
    throw DaemonError(ServeResult::failed, e.what());
  }
  if (options_.readlog) {
    // Before any port is bound: a log that cannot be replayed is refused
    // before the server says it is listening.
    try {
      check_replay_log(*options_.readlog);
    } catch (const std::exception& e) {
      logger_.error(e.what());
      throw DaemonError(ServeResult::bad_configuration, e.what());
    }
    // Replaces a plugin's readlog too: -r names what the built-in one replays.
    registry_.add(replay_driver_spec(options_));
  }
  server::ServerOptions server_options;
  server_options.bind_address = options_.bind_address;
  server_options.auth_key = options_.auth_key;
  server_ = std::make_unique<server::Server>(devices_, clock_, logger_, server_options);
}

Daemon::~Daemon() {
  if (server_) server_->stop();
  devices_.shutdown_all();
}

void Daemon::load() {
  const auto fail = [this](ServeResult result, const std::string& message) {
    logger_.error(message);
    throw DaemonError(result, message);
  };
  try {
    bind_default_port();
    std::vector<std::uint16_t> ports;
    if (options_.simulation) ports = create_world_devices();
    if (options_.has_configuration()) {
      const std::vector<std::uint16_t> configured = create_devices();
      ports.insert(ports.end(), configured.begin(), configured.end());
    }
    warn_if_nothing_replayed();
    check_served(devices_, options_.served_name());
    for (const std::string& warning : device_list_warnings(devices_)) logger_.warning(warning);
    if (std::find(ports.begin(), ports.end(), 0) != ports.end()) {
      fail(ServeResult::bad_configuration, options_.config_path + ": a robot section with port 0; only -p 0 picks a free port");
    }
    bind_ports(ports);
  } catch (const config::ConfigError& e) {
    fail(ServeResult::bad_configuration, e.what());
  } catch (const sim::worldfile::WorldFileError& e) {
    fail(ServeResult::bad_configuration, e.what());
  } catch (const server::ServerError& e) {
    fail(ServeResult::failed, e.what());
  } catch (const std::runtime_error& e) {  // a world that cannot be served
    fail(ServeResult::bad_configuration, options_.served_name() + ": " + text::printable(e.what()));
  }
}

void Daemon::bind_default_port() {
  // With -p 0 the port is only known once bound, and devices outside robot
  // sections are keyed by it: bind first, then read the configuration.
  default_port_ = options_.port;
  if (options_.port == 0) {
    default_port_ = server_->listen(0);
    bound_ports_.push_back(default_port_);
  }
}

std::vector<std::uint16_t> Daemon::create_world_devices() {
  const ServedWorld world = load_served_world(*options_.simulation, default_port_);
  for (const std::string& warning : world.warnings) logger_.warning(warning);
  register_world_drivers(registry_, world);
  const auto config = world_device_configuration(world, registry_, default_port_);
  // Every simulated device claims clock_ with the simulation's time.
  core::instantiate_devices(config, registry_, devices_, clock_, logger_);
  core::check_devices(config, devices_);
  logger_.info("simulating " + world.summary);
  return config.ports();
}

std::vector<std::uint16_t> Daemon::create_devices() {
  const auto load_options = core::load_options_for(registry_, default_port_);
  const auto config = options_.config_text
                          ? config::ConfigFile::parse(*options_.config_text, options_.config_path, load_options)
                          : config::ConfigFile::load(options_.config_path, load_options);
  for (const auto& warning : config.warnings()) logger_.warning(warning.to_string());
  // Drivers that keep time of their own claim clock_ here.
  core::instantiate_devices(config, registry_, devices_, clock_, logger_);
  core::check_devices(config, devices_);
  for (const auto& warning : config.unused_properties()) logger_.warning(warning.to_string());
  return config.ports();
}

void Daemon::bind_ports(const std::vector<std::uint16_t>& ports) {
  for (std::uint16_t port : ports) {
    if (std::find(bound_ports_.begin(), bound_ports_.end(), port) == bound_ports_.end()) {
      server_->listen(port);
      bound_ports_.push_back(port);
    }
  }
}

void Daemon::warn_if_nothing_replayed() {
  if (!options_.readlog) return;
  const auto served = devices_.all();
  if (std::none_of(served.begin(), served.end(),
                   [](const core::Device* device) { return device->info().driver_name == "readlog"; })) {
    logger_.warning("-r " + *options_.readlog + ": no device of " + options_.served_name() +
                    " has driver \"readlog\"; nothing is replayed");
  }
}

void Daemon::start() {
  try {
    // Always-on devices first: a recorder (writelog) is then listening when
    // prepare() starts a simulated world, and records it from its first step
    // even at --speedup 0, which otherwise ran to its limit before the
    // recorder was set up.
    devices_.start_alwayson();
    devices_.prepare_all();
  } catch (const std::exception& e) {
    logger_.error(e.what());
    devices_.shutdown_all();
    throw DaemonError(ServeResult::failed, e.what());
  }
}

void Daemon::run() {
  logger_.info("serving " + std::to_string(devices_.size()) + " devices");
  server_->run();
  devices_.shutdown_all();
  logger_.info("all devices shut down");
}

void Daemon::stop() { server_->stop(); }

void Daemon::stop_on_signals() { server_->stop_on_signals(); }

}  // namespace playerkit::daemon
