#pragma once
// The driver-vs-emulator test harness, written once for every hardware
// family: an emulator on a real pseudo-terminal (or a loopback TCP port) with
// its fault plan, devices built from config text naming that line the way
// the server builds them, every log line kept, and waits with deadlines for
// data, replies and the emulator's state. A family's test support adds only
// what is its own (p2os: the robot's counters; sick: a room to scan).
//
//   EmulatedLine<P2osRobotEmulator> robot([] { return std::make_unique<P2osRobotEmulator>(); });
//   ConfiguredDevices devices;
//   devices.load("sonar:0 ( driver \"p2os_sonar\" port \"$PORT\" )", robot.port());
//   ASSERT_TRUE(devices.device(protocol::kSonarCode).subscribe());
//   auto ranges = next_data<protocol::SonarData>(devices.device(protocol::kSonarCode));
//   robot.wait_until([](P2osRobotEmulator& e) { return e.sonar_enabled(); });
//
// It lives with the drivers' other test helpers because it builds devices
// from the built-in list (lib/drivers); the emulator side is lib/emulators'.

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/device.hpp"
#include "config/errors.hpp"
#include "core/logger.hpp"
#include "drivers/test_support.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "emulators/runner/fault_plan.hpp"
#include "protocol/binary_codec.hpp"

namespace playerkit::drivers::testing {

using namespace std::chrono_literals;

// Where an emulator is plugged in, and what goes wrong on the way.
struct LineOptions {
  bool tcp = false;                                // a loopback TCP port instead of a pty
  std::optional<std::filesystem::path> symlink{};  // a stable name for the pty (kept across replug)
  emulators::FaultPlan faults{};
};

// An emulator of type Emulator on a line of its own; `port()` is what a
// config's `port` says. The factory makes the device, again at every replug.
template <class Emulator>
class EmulatedLine {
 public:
  using Factory = std::function<std::unique_ptr<Emulator>()>;

  explicit EmulatedLine(Factory make, LineOptions options = {})
      : make_(std::move(make)), options_(std::move(options)) {
    plug_in();
  }

  // Where the device is plugged in (kept while it is unplugged).
  [[nodiscard]] const std::string& port() const { return port_; }
  emulators::EmulatorRunner& runner() { return *runner_; }
  [[nodiscard]] const LineOptions& options() const { return options_; }

  // Runs `read` on the emulator, its thread held off meanwhile.
  template <class Read>
  auto with(Read&& read) {
    return runner_->template with_emulator<Emulator>(std::forward<Read>(read));
  }

  // Whether `condition(emulator)` came to hold within `limit`.
  template <class Condition>
  bool wait_until(Condition condition, std::chrono::milliseconds limit = 5s) {
    return eventually([&] { return with([&](Emulator& e) { return static_cast<bool>(condition(e)); }); }, limit);
  }

  // The device unplugged (its line closed) and, unless `back` is false, a
  // fresh one from the factory (powered up anew, faults and all) plugged in
  // on the same symlink: a USB adapter pulled and put back.
  void replug(bool back = true) {
    runner_.reset();
    if (back) plug_in();
  }

 private:
  void plug_in() {
    const emulators::Endpoint endpoint = options_.tcp ? emulators::Endpoint{emulators::TcpEndpoint{}}
                                                      : emulators::Endpoint{emulators::PtyEndpoint{options_.symlink}};
    runner_ = std::make_unique<emulators::EmulatorRunner>(make_(), endpoint, options_.faults);
    port_ = runner_->device_path();
  }

  Factory make_;
  LineOptions options_;
  std::unique_ptr<emulators::EmulatorRunner> runner_;
  std::string port_;
};

// Log lines, kept for the test to read.
class LogLines {
 public:
  // From now on every line `logger` writes at its level is kept here.
  void attach(core::Logger& logger) {
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
  std::vector<std::string> lines() const {
    std::lock_guard lock(mutex_);
    std::vector<std::string> text;
    for (const auto& entry : lines_) text.push_back(entry.second);
    return text;
  }
  std::string all() const {
    std::string text;
    for (const std::string& line : lines()) text += line + "\n";
    return text;
  }
  // The first line containing every fragment, or empty if none comes within
  // `wait`: a driver changes its state and then logs it, so a test that saw
  // the change may ask a moment early.
  std::string first_with(std::initializer_list<std::string_view> fragments, std::chrono::milliseconds wait = 5s) const {
    std::string found;
    eventually(
        [&] {
          for (const std::string& line : lines()) {
            bool all_there = true;
            for (std::string_view fragment : fragments) all_there = all_there && line.find(fragment) != std::string::npos;
            if (all_there) {
              found = line;
              return true;
            }
          }
          return false;
        },
        wait);
    return found;
  }

 private:
  mutable std::mutex mutex_;
  std::vector<std::pair<core::LogLevel, std::string>> lines_;
};

// Devices made from config text, as the server makes them, their log kept.
struct ConfiguredDevices {
  ConfiguredDevices() { log.attach(builtin.logger); }

  // Instantiates every device of `text`, "$PORT" replaced by `port`; throws
  // like the server would.
  void load(std::string text, std::string_view port = {}) {
    for (std::size_t at; (at = text.find("$PORT")) != std::string::npos;) text.replace(at, 5, port);
    builtin.load(text);
  }

  core::Device& device(std::uint16_t interface, std::uint16_t index = 0) { return builtin.device(interface, index); }

  LogLines log;  // before builtin: the logger's sink refers to it
  BuiltinDevices builtin;  // last: devices shut down while the log still listens
};

// What loading `config_text` says is wrong with it, or "no error": a test
// compares messages, places included, so a config that loads fails plainly.
inline std::string config_error_of(const std::string& config_text) {
  ConfiguredDevices devices;
  try {
    devices.load(config_text);
  } catch (const config::ConfigError& e) {
    return e.what();
  }
  return "no error";
}

// The options table `readme` carries for driver `name`: the text between
// "<!-- options NAME -->" (or "<!-- options -->" when `name` is empty) on a
// line of its own and the next "<!-- end options -->". A README without them
// gives a sentence saying so, which an EXPECT_EQ against the schema's table
// then shows instead of an empty string.
inline std::string readme_options_table(const std::filesystem::path& readme, std::string_view name) {
  std::ifstream in(readme);
  if (!in) return "cannot read " + readme.string();
  std::stringstream text;
  text << in.rdbuf();
  const std::string all = text.str();
  const std::string begin = name.empty() ? "<!-- options -->\n" : "<!-- options " + std::string(name) + " -->\n";
  constexpr std::string_view kEnd = "<!-- end options -->";
  const auto start = all.find(begin);
  if (start == std::string::npos) return "no \"" + begin.substr(0, begin.size() - 1) + "\" in " + readme.string();
  const auto end = all.find(kEnd, start + begin.size());
  if (end == std::string::npos) {
    return "no \"" + std::string(kEnd) + "\" after \"" + begin.substr(0, begin.size() - 1) + "\" in " + readme.string();
  }
  return all.substr(start + begin.size(), end - start - begin.size());
}

// The value of counter `name` as `driver` reports it.
inline std::uint64_t counter(const core::Driver& driver, std::string_view name) {
  for (const core::DriverCounter& c : driver.counters()) {
    if (c.name == name) return c.value;
  }
  ADD_FAILURE() << "no counter " << name;
  return 0;
}

inline std::uint64_t data_sequence(const core::Device& device) { return device.latest_data()->sequence; }

// The device's latest data, decoded (nullopt before its first publication).
template <class Data>
std::optional<Data> latest(const core::Device& device) {
  const auto sample = device.latest_data();
  if (sample->sequence == 0) return std::nullopt;
  return protocol::decode<Data>(sample->payload);
}

// Waits for `count` more publications.
inline bool more_data(const core::Device& device, std::uint64_t count = 1, std::chrono::milliseconds limit = 5s) {
  const std::uint64_t from = data_sequence(device);
  return eventually([&] { return data_sequence(device) >= from + count; }, limit);
}

// The next data published from now on, or nullopt when none comes in `limit`.
template <class Data>
std::optional<Data> next_data(const core::Device& device, std::chrono::milliseconds limit = 5s) {
  if (!more_data(device, 1, limit)) return std::nullopt;
  return latest<Data>(device);
}

// Data satisfying `condition`, waited for; the last data seen otherwise.
template <class Data, class Condition>
std::optional<Data> data_when(const core::Device& device, Condition condition, std::chrono::milliseconds limit = 5s) {
  std::optional<Data> seen;
  eventually(
      [&] {
        seen = latest<Data>(device);
        return seen && condition(*seen);
      },
      limit);
  return seen;
}

// The first reply the device gives from now on (nullopt when none comes
// within the limit).
inline std::optional<core::Reply> next_reply(core::Device& device, std::chrono::milliseconds limit = 5s) {
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

// A request as client 1 would send it, and its reply (nullopt when none came
// within the limit). Replies left over from earlier requests are dropped first.
inline std::optional<core::Reply> ask(core::Device& device, std::vector<std::uint8_t> payload,
                                      std::chrono::milliseconds limit = 3s) {
  (void)device.take_replies();
  const auto queued = device.enqueue_request(core::Request{1, device.address(), std::move(payload), {}});
  EXPECT_EQ(queued, core::Device::RequestStatus::kQueued);
  return next_reply(device, limit);
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

// A command as client 1 would write it; it must be accepted.
template <class Command>
void write_command(core::Device& device, const Command& value) {
  const auto status = device.put_command(1, protocol::encode(value));
  EXPECT_EQ(status, core::Device::CommandStatus::kAccepted);
}

}  // namespace playerkit::drivers::testing
