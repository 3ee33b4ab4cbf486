#pragma once
// For the p2os driver tests: an emulated Pioneer and devices built from
// config text in 1.5's form, on the driver harness
// (drivers/driver_harness_test_support.hpp), which also has the bounded
// waits for data and replies.

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <utility>

#include "core/device.hpp"
#include "drivers/driver_harness_test_support.hpp"
#include "emulators/runner/fault_plan.hpp"
#include "families/p2os/driver/p2os_connection.hpp"
#include "families/p2os/driver/p2os_device_driver.hpp"
#include "families/p2os/driver/p2os_drivers.hpp"
#include "families/p2os/emulator/p2os_robot_emulator.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::drivers::p2os_testing {

// All eleven devices of one robot in 1.5's form, `$PORT` on the first: one
// section per driver spec, numbered per interface in role order
// (position:0 p2os_position, :1 p2os_compass, :2 p2os_gyro).
inline std::string every_device_config() {
  std::string text;
  std::map<std::uint16_t, int> sections_of;
  for (const core::DriverSpec& spec : p2os_driver_specs()) {
    const std::uint16_t interface = spec.interfaces.front();
    text += protocol::interface_name(interface) + ":" + std::to_string(sections_of[interface]++) + " ( driver \"" +
            spec.name + "\"" + (text.empty() ? " port \"$PORT\"" : "") + " )\n";
  }
  return text;
}
inline const std::string kEveryDevice = every_device_config();

using namespace std::chrono_literals;
using drivers::testing::acked;
using drivers::testing::ask;
using drivers::testing::data_sequence;
using drivers::testing::data_when;
using drivers::testing::eventually;
using drivers::testing::latest;
using drivers::testing::LogLines;
using drivers::testing::more_data;
using drivers::testing::nacked;
using drivers::testing::write_command;
using emulators::P2osRobotEmulator;

// A robot on a line of its own (the harness's EmulatedLine), with readers
// for what the p2os tests ask of it.
class EmulatedRobot : public drivers::testing::EmulatedLine<P2osRobotEmulator> {
 public:
  explicit EmulatedRobot(emulators::P2osEmulatorOptions options = {}, emulators::FaultPlan faults = {},
                         bool over_tcp = false)
      : EmulatedLine([options = std::move(options)] { return std::make_unique<P2osRobotEmulator>(options); },
                     {.tcp = over_tcp, .faults = faults}) {}

  std::uint64_t received(std::uint8_t command) {
    return with([command](P2osRobotEmulator& e) { return e.packets_received(command); });
  }
  bool motors_enabled() {
    return with([](P2osRobotEmulator& e) { return e.motors_enabled(); });
  }
  bool connected() {
    return with([](P2osRobotEmulator& e) { return e.connected(); });
  }
  bool wheels_stopped() {
    return with([](P2osRobotEmulator& e) {
      const auto wheels = e.wheel_velocities();
      return wheels.left == 0.0 && wheels.right == 0.0;
    });
  }
};

// Devices made from config text (the harness's ConfiguredDevices, log at
// debug level); `$PORT` in the text becomes `port`.
struct RobotDevices : drivers::testing::ConfiguredDevices {
  RobotDevices(const std::string& port, std::string text) {
    builtin.logger.set_level(core::LogLevel::kDebug);
    load(std::move(text), port);
  }

  core::Device& position(std::uint16_t index = 0) { return device(protocol::kPositionCode, index); }
  core::Device& sonar() { return device(protocol::kSonarCode); }
  core::Device& power() { return device(protocol::kPowerCode); }

  p2os::P2osConnection& connection(core::Device& any) {
    return dynamic_cast<p2os::P2osDeviceDriver&>(any.driver()).connection();
  }
  // The value of counter `name` as the device's driver reports it.
  std::uint64_t counter(core::Device& any, std::string_view name) {
    return drivers::testing::counter(any.driver(), name);
  }
};

}  // namespace playerkit::drivers::p2os_testing
