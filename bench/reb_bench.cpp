// The reb drivers on an emulated UBot (REB, LPRSerCom) on a pseudo-terminal,
// position, ir and power subscribed, all in this one process:
//
//  * CPU of the connection's I/O thread (its thread CPU clock) per cycle
//    (W, I,15, H,2, H,0 every 25 ms: the board's own pace is a command and
//    its reply every 2-3 ms) while it only follows the robot, then while
//    commands arrive every --interval ms;
//  * latency from a velocity command written to the position device
//    (Device::put_command, as the server does) to its `D,2,...` line leaving
//    on the link (the trace hook, right after write()), p50 and p99 over
//    --commands commands, each asking for another left-wheel speed.
//
//   ./build/bench/reb_bench [--seconds 10] [--commands 400] [--interval 15]
//
// Figures only; the emulator shares the machine (its own thread).

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <mutex>
#include <optional>
#include <random>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include "config/config_file.hpp"
#include "core/server_clock.hpp"
#include "core/clock.hpp"
#include "core/device_table.hpp"
#include "core/driver_registry.hpp"
#include "core/instantiate.hpp"
#include "core/logger.hpp"
#include "drivers/builtin.hpp"
#include "families/reb/driver/reb_device_driver.hpp"
#include "families/reb/emulator/reb_emulator.hpp"
#include "families/reb/protocol/reb_params.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/position.hpp"

namespace {

using namespace playerkit;
using namespace std::chrono_literals;
using SteadyClock = std::chrono::steady_clock;

struct Options {
  int seconds = 10;     // CPU measurement while only following the robot
  int commands = 400;   // latency samples
  int interval_ms = 15; // between commands
};

Options parse(int argc, char** argv) {
  Options options;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string name = argv[i];
    const int value = std::atoi(argv[i + 1]);
    if (name == "--seconds") options.seconds = std::max(1, value);
    else if (name == "--commands") options.commands = std::max(10, value);
    else if (name == "--interval") options.interval_ms = std::max(1, value);
    else {
      std::fprintf(stderr, "reb_bench: unknown option %s (--seconds, --commands, --interval)\n", name.c_str());
      std::exit(2);
    }
  }
  return options;
}

// The left motor's set-point in the latest `D,2,v` line that left, by the trace hook.
struct SpeedWatch {
  std::mutex mutex;
  std::condition_variable changed;
  std::optional<int> wanted;  // the pulses per 10 ms awaited
  std::optional<SteadyClock::time_point> seen_at;

  void on_bytes(bool outgoing, std::span<const std::uint8_t> bytes, SteadyClock::time_point when) {
    const std::string text(bytes.begin(), bytes.end());
    if (!outgoing || text.rfind("D,2,", 0) != 0) return;
    const int value = std::atoi(text.c_str() + 4);
    std::lock_guard lock(mutex);
    if (wanted && value == *wanted && !seen_at) {
      seen_at = when;
      changed.notify_all();
    }
  }
};

double percentile(std::vector<double> values, double p) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const auto index = static_cast<std::size_t>(p * static_cast<double>(values.size() - 1) + 0.5);
  return values[std::min(index, values.size() - 1)];
}

double milliseconds(std::chrono::nanoseconds d) { return std::chrono::duration<double, std::milli>(d).count(); }

}  // namespace

int main(int argc, char** argv) {
  const Options options = parse(argc, argv);

  emulators::EmulatorRunner robot(std::make_unique<emulators::RebEmulator>(emulators::RebEmulatorOptions{}),
                                  emulators::PtyEndpoint{});

  core::ServerClock clock;  // the wall clock: no driver here claims it
  core::Logger logger("reb_bench");
  logger.set_level(core::LogLevel::kWarning);
  core::DriverRegistry registry;
  drivers::register_builtin_drivers(registry);
  core::DeviceTable devices;
  const std::string text = "position:0 ( driver \"reb_position\" port \"" + robot.device_path() +
                           "\" subclass \"slow\" )\n"
                           "ir:0 ( driver \"reb_ir\" )\n"
                           "power:0 ( driver \"reb_power\" )\n";
  core::instantiate_devices(config::ConfigFile::parse(text, "bench.cfg", core::load_options_for(registry, 6665)),
                            registry, devices, clock, logger);
  core::Device& position = *devices.find(6665, {protocol::kPositionCode, 0});

  SpeedWatch watch;
  position.driver().set_byte_trace(
      [&watch](bool outgoing, std::span<const std::uint8_t> bytes, SteadyClock::time_point when) {
        watch.on_bytes(outgoing, bytes, when);
      });
  for (core::Device* device : devices.all()) {
    if (!device->subscribe()) {
      std::fprintf(stderr, "reb_bench: %s could not be subscribed\n", device->name().c_str());
      return 1;
    }
  }
  auto& connection = dynamic_cast<drivers::reb::RebDeviceDriver&>(position.driver()).connection();
  auto counter = [&connection](std::string_view name) -> std::uint64_t {
    for (const auto& c : connection.counters()) {
      if (c.name == name) return c.value;
    }
    return 0;
  };
  (void)position.enqueue_request(core::Request{1, position.address(),
                                               protocol::encode(protocol::PositionPowerConfig{2, 1}), {}});

  // 1. Following the robot: a poll of the board and three publications a cycle.
  std::this_thread::sleep_for(500ms);
  auto cpu_before = connection.io_thread_cpu_time();
  auto cycles_before = counter("cycles");
  auto wall_before = SteadyClock::now();
  std::this_thread::sleep_for(std::chrono::seconds(options.seconds));
  auto cpu_after = connection.io_thread_cpu_time();
  const double idle_wall = milliseconds(SteadyClock::now() - wall_before);
  const double idle_cpu = cpu_before && cpu_after ? milliseconds(*cpu_after - *cpu_before) : -1.0;
  const auto idle_cycles = counter("cycles") - cycles_before;

  // 2. Commands every interval, at random phases: latency to the wire, and CPU meanwhile.
  const hardware::reb::RebParams& slow = hardware::reb::params_for("slow");
  std::vector<double> latencies;
  int missed = 0;
  cpu_before = connection.io_thread_cpu_time();
  cycles_before = counter("cycles");
  wall_before = SteadyClock::now();
  std::mt19937 random(1);
  std::uniform_int_distribution<int> jitter_us(0, 5000);
  for (int i = 0; i < options.commands; ++i) {
    protocol::PositionCommand command;
    command.xspeed = (1 + i % 30) * 20;  // 20 ... 600 mm/s, never the previous one
    {
      std::lock_guard lock(watch.mutex);
      watch.wanted = hardware::reb::motor_speeds(command.xspeed, 0.0, slow).left;
      watch.seen_at.reset();
    }
    const auto sent = SteadyClock::now();
    position.put_command(1, protocol::encode(command));
    std::unique_lock lock(watch.mutex);
    if (watch.changed.wait_for(lock, 1s, [&] { return watch.seen_at.has_value(); })) {
      latencies.push_back(milliseconds(*watch.seen_at - sent));
    } else {
      ++missed;
    }
    lock.unlock();
    std::this_thread::sleep_for(std::chrono::milliseconds(options.interval_ms) +
                                std::chrono::microseconds(jitter_us(random)));
  }
  cpu_after = connection.io_thread_cpu_time();
  const double busy_wall = milliseconds(SteadyClock::now() - wall_before);
  const double busy_cpu = cpu_before && cpu_after ? milliseconds(*cpu_after - *cpu_before) : -1.0;
  const auto busy_cycles = counter("cycles") - cycles_before;

  position.put_command(1, protocol::encode(protocol::PositionCommand{}));
  devices.shutdown_all();

  std::printf("reb_bench: UBot (slow) emulated on %s; position, ir, power subscribed\n", robot.device_path().c_str());
  std::printf("following the robot: %.1f s, %llu cycles (%.1f /s)\n", idle_wall / 1000.0,
              static_cast<unsigned long long>(idle_cycles), static_cast<double>(idle_cycles) * 1000.0 / idle_wall);
  std::printf("  I/O thread CPU: %.1f ms (%.2f %% of one core, %.1f us per cycle)\n", idle_cpu,
              100.0 * idle_cpu / idle_wall,
              idle_cycles > 0 ? 1000.0 * idle_cpu / static_cast<double>(idle_cycles) : 0.0);
  std::printf("commands: %d velocity commands every %d ms over %.1f s, %llu cycles\n", options.commands,
              options.interval_ms, busy_wall / 1000.0, static_cast<unsigned long long>(busy_cycles));
  std::printf("  I/O thread CPU: %.1f ms (%.2f %% of one core)\n", busy_cpu, 100.0 * busy_cpu / busy_wall);
  std::printf("  put_command -> D,2 written: p50 %.2f ms, p99 %.2f ms, max %.2f ms (%zu samples, %d missed)\n",
              percentile(latencies, 0.5), percentile(latencies, 0.99), percentile(latencies, 1.0),
              latencies.size(), missed);
  return 0;
}
