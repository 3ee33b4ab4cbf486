#include "daemon/serve.hpp"


#include "core/plugin.hpp"
#include "daemon/daemon.hpp"
#include "drivers/builtin.hpp"

namespace playerkit::daemon {

std::string ServeOptions::served_name() const {
  if (has_configuration() || !simulation) return config_path;
  return simulation->world;
}

core::DriverRegistry load_drivers(const std::vector<std::string>& plugins, core::Logger& logger) {
  core::DriverRegistry registry;
  drivers::register_builtin_drivers(registry);
  for (const std::string& plugin : plugins) {
    core::load_driver_plugin(plugin, registry);
    logger.info("loaded plugin " + plugin);
  }
  return registry;
}

ServeResult serve(const ServeOptions& options) {
  try {
    Daemon daemon(options);
    daemon.load();
    daemon.start();
    daemon.stop_on_signals();
    daemon.run();
    return ServeResult::stopped;
  } catch (const DaemonError& e) {
    return e.result();  // logged by the daemon
  }
}

}  // namespace playerkit::daemon
