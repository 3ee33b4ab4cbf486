#pragma once
// Serving in steps, for programs that need the devices in their hands while
// they are served (player-drivers run reads a driver's link counters and
// traces its bytes); serve() is these steps run until a signal.
//
//   daemon::Daemon daemon(options);      // registry: drivers loaded, server made
//   daemon.load();                       // devices from the world and the configuration, ports bound
//   daemon.start();                      // prepare, alwayson devices up
//   std::jthread serving([&] { daemon.run(); });
//   ... daemon.devices() ..., daemon.stop();

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <vector>

#include "core/device_table.hpp"
#include "core/driver_registry.hpp"
#include "core/logger.hpp"
#include "core/server_clock.hpp"
#include "config/config_file.hpp"
#include "daemon/serve.hpp"

namespace playerkit::server {
class Server;
}

namespace playerkit::daemon {

// A step failed. The message is logged already.
class DaemonError : public std::runtime_error {
 public:
  DaemonError(ServeResult result, const std::string& message) : std::runtime_error(message), result_(result) {}
  [[nodiscard]] ServeResult result() const { return result_; }

 private:
  ServeResult result_;
};

class Daemon {
 public:
  // Loads the drivers (built-in, plugins, -r's readlog). Throws DaemonError.
  explicit Daemon(ServeOptions options);
  ~Daemon();
  Daemon(const Daemon&) = delete;
  Daemon& operator=(const Daemon&) = delete;

  // Loads the -s world, reads the configuration, creates the devices and
  // binds every port. Throws DaemonError.
  void load();
  // prepare() on every device, then the alwayson ones. Throws DaemonError
  // (the devices are shut down again).
  void start();
  // Serves until stop() (or a signal, after stop_on_signals()), then shuts
  // every device down.
  void run();
  void stop();
  void stop_on_signals();

  // The port devices outside robot sections are served on (chosen when -p 0).
  [[nodiscard]] std::uint16_t default_port() const { return default_port_; }
  [[nodiscard]] core::DeviceTable& devices() { return devices_; }
  [[nodiscard]] const core::DriverRegistry& registry() const { return registry_; }
  [[nodiscard]] core::Logger& logger() { return logger_; }
  // The wall clock, unless a driver family keeps time of its own (readlog's
  // -r log, a simulation) and claimed it while the devices were created.
  [[nodiscard]] const core::ServerClock& clock() const { return clock_; }

 private:
  // The steps of load(), in order. Each throws what it meets.
  void bind_default_port();
  // -s: the world's devices (simulation.hpp); the ports they are served on.
  std::vector<std::uint16_t> create_world_devices();
  // The configuration's devices; the ports its robot sections name.
  std::vector<std::uint16_t> create_devices();
  void bind_ports(const std::vector<std::uint16_t>& ports);
  void warn_if_nothing_replayed();

  ServeOptions options_;
  core::Logger logger_;
  core::ServerClock clock_;  // before the devices and the server, which read it
  core::DriverRegistry registry_;
  core::DeviceTable devices_;
  std::unique_ptr<server::Server> server_;
  std::uint16_t default_port_ = 0;
  std::vector<std::uint16_t> bound_ports_;
};

}  // namespace playerkit::daemon
