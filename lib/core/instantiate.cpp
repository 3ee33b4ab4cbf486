#include "core/instantiate.hpp"

#include <algorithm>
#include <exception>
#include <string>

#include "config/errors.hpp"
#include "core/option_reader.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::core {

namespace {

std::string interface_list(const DriverSpec& spec) {
  std::string names;
  for (std::uint16_t code : spec.interfaces) {
    if (!names.empty()) names += ", ";
    names += protocol::interface_name(code);
  }
  return names.empty() ? "nothing" : names;
}

}  // namespace

config::LoadOptions load_options_for(const DriverRegistry& registry, std::uint16_t default_port) {
  config::LoadOptions options;
  options.default_port = default_port;
  options.driver_exists = [&registry](std::string_view name) { return registry.contains(name); };
  return options;
}

void instantiate_devices(const config::ConfigFile& config, const DriverRegistry& registry,
                         DeviceTable& devices, ServerClock& clock, Logger& logger) {
  for (const config::DeviceDeclaration& declaration : config.devices()) {
    const DriverSpec* spec = registry.find(declaration.driver);
    if (spec == nullptr) {
      throw config::ConfigError(declaration.where,
                                "driver '" + declaration.driver + "' is not available");
    }
    if (!spec->doc.unavailable.empty()) {
      const config::Property* named = config.section(declaration.section).property("driver");
      const bool written = named != nullptr && !named->values.empty();
      throw config::ConfigError(written ? named->values.front().where : declaration.where,
                                "driver '" + spec->name + "' cannot run: " + spec->doc.unavailable);
    }
    const auto& codes = spec->interfaces;
    if (std::find(codes.begin(), codes.end(), declaration.address.interface) == codes.end()) {
      throw config::ConfigError(declaration.where, "driver '" + spec->name +
                                                       "' does not serve interface '" +
                                                       declaration.interface_name +
                                                       "' (it serves " + interface_list(*spec) + ")");
    }
    const DeviceKey key{declaration.port, declaration.address};
    const DriverContext context{config,     config.section(declaration.section),
                                key,        declaration.robot_name,
                                devices,    clock,
                                logger,     devices.connections()};
    std::unique_ptr<Driver> driver;
    try {
      // Every declared option the section writes is checked here, whether or
      // not the factory reads it in this configuration.
      OptionReader(context.section, spec->name, spec->doc.schema).validate();
      driver = spec->factory(context);
    } catch (const config::ConfigError&) {
      throw;
    } catch (const ClockClaimError& e) {
      throw config::ConfigError(declaration.where, e.what());
    } catch (const std::exception& e) {
      throw config::ConfigError(declaration.where,
                                "driver '" + spec->name + "' could not be created: " + e.what());
    }
    if (!driver) {
      throw config::ConfigError(declaration.where,
                                "driver '" + spec->name + "' could not be created");
    }
    DeviceInfo info{spec->name, declaration.robot_name, spec->access,
                    spec->limits_for(key.address.interface),
                    declaration.alwayson};
    devices.add(std::make_unique<Device>(key, std::move(info), std::move(driver), clock, logger));
  }
}

void check_devices(const config::ConfigFile& config, DeviceTable& devices) {
  for (const config::DeviceDeclaration& declaration : config.devices()) {
    Device* device = devices.find(DeviceKey{declaration.port, declaration.address});
    if (device == nullptr) continue;
    try {
      device->check();
    } catch (const DriverError& e) {
      throw config::ConfigError(declaration.where, e.what());
    }
  }
}

}  // namespace playerkit::core
