#pragma once
// Helpers for the driver tests: real devices built the way the server builds
// them (registry + config text + instantiate_devices), and bounded waiting for
// things that happen on other threads.

#include <cstdint>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "config/config_file.hpp"
#include "core/clock.hpp"
#include "core/device.hpp"
#include "core/device_table.hpp"
#include "core/driver_registry.hpp"
#include "core/instantiate.hpp"
#include "core/logger.hpp"
#include "core/server_clock.hpp"
#include "drivers/builtin.hpp"
#include "support/eventually.hpp"

namespace playerkit::drivers::testing {

inline constexpr std::uint16_t kTestPort = 6665;

using ::playerkit::testing::eventually;

// A request as the server would queue it for client 1.
inline core::Request make_request(std::uint16_t interface, std::vector<std::uint8_t> payload) {
  return core::Request{1, {interface, 0}, std::move(payload), {}};
}

// The built-in registry and devices made from config text, with a silent log.
struct BuiltinDevices {
  BuiltinDevices() {
    logger.set_sink([](core::LogLevel, std::string_view) {});
    register_builtin_drivers(registry);
  }

  // Instantiates every device declared in `text`; throws like the server would.
  void load(std::string_view text) {
    const auto config =
        config::ConfigFile::parse(text, "test.cfg", core::load_options_for(registry, kTestPort));
    core::instantiate_devices(config, registry, devices, clock, logger);
  }

  core::Device& device(std::uint16_t interface, std::uint16_t index = 0) {
    core::Device* found = devices.find(kTestPort, {interface, index});
    if (found == nullptr) throw std::runtime_error("test device not declared");
    return *found;
  }

  core::ServerClock clock;  // the wall clock unless a driver claims it
  core::Logger logger;
  core::DriverRegistry registry;
  core::DeviceTable devices;  // last: devices shut down before the rest goes
};

}  // namespace playerkit::drivers::testing
