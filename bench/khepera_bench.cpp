// khepera_position and khepera_ir against the emulated Khepera on a
// pseudo-terminal, both subscribed, all in this one process:
//
//  * CPU of the connection's I/O thread (its thread CPU clock) per cycle
//    (D, N, H, E and the publishing) at the default 50 ms cycle_time;
//  * latency from a velocity command written to the position device
//    (Device::put_command, as the server does) to its `D,l,r` leaving on the
//    line (the link's trace hook, right after write()), p50 and p99 over
//    --commands commands, each a speed the previous one was not.
//
//   ./build/bench/khepera_bench [--seconds 10] [--commands 400] [--interval 15]
//
// Figures only; the emulator shares the machine (its own thread).

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <mutex>
#include <optional>
#include <random>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include "config/config_file.hpp"
#include "core/device_table.hpp"
#include "core/driver_registry.hpp"
#include "core/instantiate.hpp"
#include "core/logger.hpp"
#include "core/server_clock.hpp"
#include "drivers/builtin.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "families/khepera/driver/khepera_device_driver.hpp"
#include "families/khepera/emulator/khepera_emulator.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/position.hpp"

namespace {

using namespace playerkit;
using namespace std::chrono_literals;
using SteadyClock = std::chrono::steady_clock;

struct Options {
  int seconds = 10;
  int commands = 400;
  int interval_ms = 15;
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
      std::fprintf(stderr, "khepera_bench: unknown option %s (--seconds, --commands, --interval)\n", name.c_str());
      std::exit(2);
    }
  }
  return options;
}

// The first `D,<wanted>,` written since it was armed, by the trace hook.
struct SpeedWatch {
  std::mutex mutex;
  std::condition_variable changed;
  std::string wanted;
  std::optional<SteadyClock::time_point> seen_at;

  void on_bytes(bool outgoing, std::span<const std::uint8_t> bytes, SteadyClock::time_point when) {
    if (!outgoing) return;
    const std::string text(bytes.begin(), bytes.end());
    std::lock_guard lock(mutex);
    if (!wanted.empty() && !seen_at && text.rfind(wanted, 0) == 0) {
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
  emulators::EmulatorRunner robot(std::make_unique<emulators::KheperaEmulator>(), emulators::PtyEndpoint{});

  core::ServerClock clock;
  core::Logger logger("khepera_bench");
  logger.set_level(core::LogLevel::kWarning);
  core::DriverRegistry registry;
  drivers::register_builtin_drivers(registry);
  core::DeviceTable devices;
  const std::string text = "position:0 ( driver \"khepera_position\" port \"" + robot.device_path() +
                           "\" )\nir:0 ( driver \"khepera_ir\" )\n";
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
      std::fprintf(stderr, "khepera_bench: %s could not be subscribed\n", device->name().c_str());
      return 1;
    }
  }
  auto& connection = dynamic_cast<drivers::khepera::KheperaDeviceDriver&>(position.driver()).connection();
  auto counter = [&connection](std::string_view name) -> std::uint64_t {
    for (const auto& c : connection.counters()) {
      if (c.name == name) return c.value;
    }
    return 0;
  };
  // MOTOR_POWER on, through the device's queue as a client's request goes.
  core::Request power;
  power.client = 1;
  power.device = {protocol::kPositionCode, 0};
  power.payload =
      protocol::encode(protocol::PositionPowerConfig{.request = protocol::kPositionMotorPowerReq, .value = 1});
  (void)position.enqueue_request(power);
  bool powered = false;
  for (const auto until = SteadyClock::now() + 2s; !powered && SteadyClock::now() < until;) {
    for (const core::Reply& reply : position.take_replies()) powered = reply.type == protocol::MessageType::kAck;
    if (!powered) std::this_thread::sleep_for(5ms);
  }
  if (!powered) {
    std::fprintf(stderr, "khepera_bench: MOTOR_POWER was not ACKed\n");
    return 1;
  }

  // 1. Following the robot: a cycle of D, N, H, E and both devices published.
  std::this_thread::sleep_for(500ms);
  auto cpu_before = connection.io_thread_cpu_time();
  auto cycles_before = counter("cycles");
  auto wall_before = SteadyClock::now();
  std::this_thread::sleep_for(std::chrono::seconds(options.seconds));
  auto cpu_after = connection.io_thread_cpu_time();
  const double idle_wall = milliseconds(SteadyClock::now() - wall_before);
  const double idle_cpu = cpu_before && cpu_after ? milliseconds(*cpu_after - *cpu_before) : -1.0;
  const auto idle_cycles = counter("cycles") - cycles_before;

  // 2. Commands at random phases: latency to the wire, and CPU meanwhile.
  std::vector<double> latencies;
  int missed = 0;
  cpu_before = connection.io_thread_cpu_time();
  wall_before = SteadyClock::now();
  std::mt19937 random(1);
  std::uniform_int_distribution<int> jitter_us(0, 5000);
  for (int i = 0; i < options.commands; ++i) {
    const int units = 1 + i % 40;  // 25 ... 1000 mm/s: 3 ... 120 pulses, never the previous one
    protocol::PositionCommand command;
    command.xspeed = units * 25;
    {
      std::lock_guard lock(watch.mutex);
      watch.wanted = "D," + std::to_string(3 * units) + ",";
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

  position.put_command(1, protocol::encode(protocol::PositionCommand{}));
  devices.shutdown_all();

  std::printf("khepera_bench: Khepera emulated on %s; position and ir subscribed, cycle_time 50 ms\n",
              robot.device_path().c_str());
  std::printf("following the robot: %.1f s, %llu cycles (%.1f /s)\n", idle_wall / 1000.0,
              static_cast<unsigned long long>(idle_cycles), static_cast<double>(idle_cycles) * 1000.0 / idle_wall);
  std::printf("  I/O thread CPU: %.1f ms (%.2f %% of one core, %.1f us per cycle)\n", idle_cpu,
              100.0 * idle_cpu / idle_wall,
              idle_cycles > 0 ? 1000.0 * idle_cpu / static_cast<double>(idle_cycles) : 0.0);
  std::printf("commands: %d velocity commands every %d ms over %.1f s\n", options.commands, options.interval_ms,
              busy_wall / 1000.0);
  std::printf("  I/O thread CPU: %.1f ms (%.2f %% of one core)\n", busy_cpu, 100.0 * busy_cpu / busy_wall);
  std::printf("  put_command -> D,l,r written: p50 %.2f ms, p99 %.2f ms, max %.2f ms (%zu samples, %d missed)\n",
              percentile(latencies, 0.5), percentile(latencies, 0.99), percentile(latencies, 1.0),
              latencies.size(), missed);
  return 0;
}
