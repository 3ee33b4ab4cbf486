#pragma once
// For the p2os driver tests: an emulated Pioneer on a pseudo-terminal (or a
// loopback TCP port) that the test creates, devices built from config text
// in 1.5's form, and bounded waits for what the I/O thread does.

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/device.hpp"
#include "families/p2os/driver/p2os_connection.hpp"
#include "families/p2os/driver/p2os_device_driver.hpp"
#include "drivers/test_support.hpp"
#include "families/p2os/emulator/p2os_robot_emulator.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "emulators/runner/fault_plan.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::drivers::p2os_testing {

// All eleven devices of one robot in 1.5's form, `port` on the first
// (replace $PORT).
inline constexpr std::string_view kEveryDevice =
    "position:0 ( driver \"p2os_position\" port \"$PORT\" )\n"
    "sonar:0 ( driver \"p2os_sonar\" )\n"
    "gripper:0 ( driver \"p2os_gripper\" )\n"
    "power:0 ( driver \"p2os_power\" )\n"
    "bumper:0 ( driver \"p2os_bumper\" )\n"
    "aio:0 ( driver \"p2os_aio\" )\n"
    "dio:0 ( driver \"p2os_dio\" )\n"
    "blobfinder:0 ( driver \"p2os_cmucam\" )\n"
    "position:1 ( driver \"p2os_compass\" )\n"
    "position:2 ( driver \"p2os_gyro\" )\n"
    "sound:0 ( driver \"p2os_sound\" )\n";

using namespace std::chrono_literals;
using drivers::testing::eventually;
using emulators::P2osRobotEmulator;

// A robot on a line of its own; `port()` is what the config's `port` says.
class EmulatedRobot {
 public:
  explicit EmulatedRobot(emulators::P2osEmulatorOptions options = {}, emulators::FaultPlan faults = {},
                         bool over_tcp = false)
      : runner_(std::make_unique<P2osRobotEmulator>(std::move(options)),
                over_tcp ? emulators::Endpoint{emulators::TcpEndpoint{}}
                         : emulators::Endpoint{emulators::PtyEndpoint{}},
                faults) {}

  [[nodiscard]] const std::string& port() const { return runner_.device_path(); }
  emulators::EmulatorRunner& runner() { return runner_; }

  // Runs `read` on the emulator, its thread held off meanwhile.
  template <class Read>
  auto with(Read&& read) {
    return runner_.with_emulator<P2osRobotEmulator>(std::forward<Read>(read));
  }
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

 private:
  emulators::EmulatorRunner runner_;
};

// Log lines, kept for the test to read.
class LogLines {
 public:
  void attach(core::Logger& logger) {
    logger.set_level(core::LogLevel::kDebug);
    logger.set_sink([this](core::LogLevel level, std::string_view line) {
      std::lock_guard lock(mutex_);
      lines_.push_back({level, std::string(line)});
    });
  }
  // Lines at `level` or worse that contain `text`.
  std::size_t count(std::string_view text, core::LogLevel level = core::LogLevel::kInfo) const {
    std::lock_guard lock(mutex_);
    std::size_t n = 0;
    for (const auto& [line_level, line] : lines_) {
      if (line_level <= level && line.find(text) != std::string::npos) ++n;
    }
    return n;
  }
  std::string all() const {
    std::lock_guard lock(mutex_);
    std::string text;
    for (const auto& entry : lines_) text += entry.second + "\n";
    return text;
  }

 private:
  mutable std::mutex mutex_;
  std::vector<std::pair<core::LogLevel, std::string>> lines_;
};

// Devices made from config text; `$PORT` in the text becomes `port`.
struct RobotDevices {
  RobotDevices(const std::string& port, std::string text) {
    log.attach(builtin.logger);
    for (std::size_t at; (at = text.find("$PORT")) != std::string::npos;) text.replace(at, 5, port);
    builtin.load(text);
  }

  core::Device& device(std::uint16_t interface, std::uint16_t index = 0) {
    return builtin.device(interface, index);
  }
  core::Device& position(std::uint16_t index = 0) { return device(protocol::kPositionCode, index); }
  core::Device& sonar() { return device(protocol::kSonarCode); }
  core::Device& power() { return device(protocol::kPowerCode); }

  p2os::P2osConnection& connection(core::Device& any) {
    return dynamic_cast<p2os::P2osDeviceDriver&>(any.driver()).connection();
  }
  // The value of counter `name` as the device's driver reports it.
  std::uint64_t counter(core::Device& any, std::string_view name) {
    for (const core::DriverCounter& c : any.driver().counters()) {
      if (c.name == name) return c.value;
    }
    ADD_FAILURE() << "no counter " << name;
    return 0;
  }

  LogLines log;  // before builtin: the logger's sink refers to it
  drivers::testing::BuiltinDevices builtin;
};

// The device's latest data, decoded (nullopt before its first publication).
template <class Data>
std::optional<Data> latest(const core::Device& device) {
  const auto sample = device.latest_data();
  if (sample->sequence == 0) return std::nullopt;
  return protocol::decode<Data>(sample->payload);
}

inline std::uint64_t data_sequence(const core::Device& device) { return device.latest_data()->sequence; }

// Waits for `count` more publications.
inline bool more_data(const core::Device& device, std::uint64_t count = 1,
                      std::chrono::milliseconds limit = 5s) {
  const std::uint64_t from = data_sequence(device);
  return eventually([&] { return data_sequence(device) >= from + count; }, limit);
}

// Data satisfying `condition`, waited for; the last data seen otherwise.
template <class Data, class Condition>
std::optional<Data> data_when(const core::Device& device, Condition condition,
                              std::chrono::milliseconds limit = 5s) {
  std::optional<Data> seen;
  eventually(
      [&] {
        seen = latest<Data>(device);
        return seen && condition(*seen);
      },
      limit);
  return seen;
}

// A request as a client would send it, and its reply (nullopt when none
// came within the limit).
inline std::optional<core::Reply> ask(core::Device& device, std::vector<std::uint8_t> payload,
                                      std::chrono::milliseconds limit = 3s) {
  (void)device.take_replies();
  const auto queued = device.enqueue_request(core::Request{1, device.address(), std::move(payload), {}});
  EXPECT_EQ(queued, core::Device::RequestStatus::kQueued);
  std::optional<core::Reply> reply;
  eventually(
      [&] {
        auto replies = device.take_replies();
        if (!replies.empty()) reply = std::move(replies.front());
        return reply.has_value();
      },
      limit);
  return reply;
}

template <class Request>
std::optional<core::Reply> ask(core::Device& device, const Request& request, std::chrono::milliseconds limit = 3s) {
  return ask(device, protocol::encode(request), limit);
}

inline bool acked(const std::optional<core::Reply>& reply) {
  return reply && reply->type == protocol::MessageType::kAck;
}
inline bool nacked(const std::optional<core::Reply>& reply) {
  return reply && reply->type == protocol::MessageType::kNack;
}

template <class Command>
void write_command(core::Device& device, const Command& value) {
  const auto status = device.put_command(1, protocol::encode(value));
  EXPECT_EQ(status, core::Device::CommandStatus::kAccepted);
}

}  // namespace playerkit::drivers::p2os_testing
