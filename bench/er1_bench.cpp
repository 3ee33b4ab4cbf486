// er1_position against the emulated ER1 on a pseudo-terminal (230400 baud
// as far as a pty has one), in this one process:
//
//  * CPU of the driver's thread per cycle (its thread CPU clock, read by a
//    listener the driver calls after each publication): two position reads
//    and the odometry, 50 times a second, while the robot is only followed;
//  * latency from a velocity command written to the device
//    (Device::put_command, as the server does) to its bytes on the line
//    (the link's trace hook, right after write()): to the first command
//    of the speed sequence, and to the EXECUTE of motor 1 that sets both
//    wheels going, p50 and p99 over --commands commands. Each command asks
//    for another speed, so its bytes are told apart.
//
//   ./build/bench/er1_bench [--seconds 10] [--commands 300] [--interval 40]
//
// Figures only; the emulator shares the machine (its own thread).

#include <time.h>

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
#include <utility>
#include <vector>

#include "config/config_file.hpp"
#include "core/device_table.hpp"
#include "core/driver_registry.hpp"
#include "core/instantiate.hpp"
#include "core/logger.hpp"
#include "core/server_clock.hpp"
#include "drivers/builtin.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "families/er1/emulator/er1_emulator.hpp"
#include "families/er1/protocol/er1_commands.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/position.hpp"

namespace {

using namespace playerkit;
using namespace std::chrono_literals;
using SteadyClock = std::chrono::steady_clock;
namespace rcm = hardware::er1;

struct Options {
  int seconds = 10;
  int commands = 300;
  int interval_ms = 40;
};

Options parse(int argc, char** argv) {
  Options options;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string name = argv[i];
    const int value = std::atoi(argv[i + 1]);
    if (name == "--seconds") options.seconds = std::max(1, value);
    else if (name == "--commands") options.commands = std::max(10, value);
    else if (name == "--interval") options.interval_ms = std::max(5, value);
    else {
      std::fprintf(stderr, "er1_bench: unknown option %s (--seconds, --commands, --interval)\n", name.c_str());
      std::exit(2);
    }
  }
  return options;
}

std::chrono::nanoseconds thread_cpu() {
  timespec cpu{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &cpu);
  return std::chrono::seconds(cpu.tv_sec) + std::chrono::nanoseconds(cpu.tv_nsec);
}

// The driver thread's CPU clock at each publication.
class PublishRecorder final : public core::DeviceListener {
 public:
  void data_published(const core::Device&) override {
    const auto cpu = thread_cpu();
    std::lock_guard lock(mutex_);
    cpu_.push_back(cpu);
  }
  void replies_ready(const core::Device&) override {}
  std::vector<std::chrono::nanoseconds> take() {
    std::lock_guard lock(mutex_);
    return std::exchange(cpu_, {});
  }

 private:
  std::mutex mutex_;
  std::vector<std::chrono::nanoseconds> cpu_;
};

// A command's way onto the line: its first write, and motor 1's EXECUTE
// after motor 1's velocity register took the value awaited.
struct CommandWatch {
  std::mutex mutex;
  std::condition_variable changed;
  std::optional<std::int32_t> wanted;  // motor 1's speed register
  bool value_sent = false;
  std::optional<SteadyClock::time_point> first_write;
  std::optional<SteadyClock::time_point> executed;

  void on_bytes(bool outgoing, std::span<const std::uint8_t> bytes, SteadyClock::time_point when) {
    if (!outgoing || bytes.size() < 4) return;
    std::lock_guard lock(mutex);
    if (!wanted) return;
    if (!first_write && bytes[0] == 0 && bytes[3] == rcm::opcode::read_status) first_write = when;
    if (bytes[0] == 1 && bytes[3] == rcm::opcode::velocity && bytes.size() == 8) {
      const auto value = static_cast<std::int32_t>((std::uint32_t{bytes[4]} << 24) | (std::uint32_t{bytes[5]} << 16) |
                                                   (std::uint32_t{bytes[6]} << 8) | bytes[7]);
      value_sent = value == *wanted;
    }
    if (value_sent && !executed && bytes[0] == 1 && bytes[3] == rcm::opcode::execute) {
      executed = when;
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
  emulators::EmulatorRunner robot(std::make_unique<emulators::Er1Emulator>(), emulators::PtyEndpoint{});

  core::ServerClock clock;
  core::Logger logger("er1_bench");
  logger.set_level(core::LogLevel::kWarning);
  core::DriverRegistry registry;
  drivers::register_builtin_drivers(registry);
  core::DeviceTable devices;
  const std::string text = "position:0 ( driver \"er1_position\" port \"" + robot.device_path() + "\" )\n";
  core::instantiate_devices(config::ConfigFile::parse(text, "bench.cfg", core::load_options_for(registry, 6665)),
                            registry, devices, clock, logger);
  core::Device& position = *devices.find(6665, {protocol::kPositionCode, 0});

  CommandWatch watch;
  position.driver().set_byte_trace(
      [&watch](bool outgoing, std::span<const std::uint8_t> bytes, SteadyClock::time_point when) {
        watch.on_bytes(outgoing, bytes, when);
      });
  PublishRecorder recorder;
  position.add_listener(&recorder);
  if (!position.subscribe()) {
    std::fprintf(stderr, "er1_bench: the driver did not set up\n");
    return 1;
  }

  // 1. Following the robot.
  std::this_thread::sleep_for(500ms);
  (void)recorder.take();
  const auto wall_before = SteadyClock::now();
  std::this_thread::sleep_for(std::chrono::seconds(options.seconds));
  const double idle_wall = milliseconds(SteadyClock::now() - wall_before);
  const auto cycles = recorder.take();
  const double cpu_per_cycle_us =
      cycles.size() > 1 ? std::chrono::duration<double, std::micro>(cycles.back() - cycles.front()).count() /
                              static_cast<double>(cycles.size() - 1)
                        : 0.0;

  // 2. Commands at random phases.
  std::vector<double> to_first_write;
  std::vector<double> to_execute;
  int missed = 0;
  std::mt19937 random(1);
  std::uniform_int_distribution<int> jitter_us(0, 20000);
  for (int i = 0; i < options.commands; ++i) {
    protocol::PositionCommand command;
    command.xspeed = 10 + 10 * (i % 40);  // 10 ... 400 mm/s, never the previous one
    {
      std::lock_guard lock(watch.mutex);
      watch.wanted = rcm::speed_register(command.xspeed);
      watch.value_sent = false;
      watch.first_write.reset();
      watch.executed.reset();
    }
    const auto sent = SteadyClock::now();
    position.put_command(1, protocol::encode(command));
    std::unique_lock lock(watch.mutex);
    if (watch.changed.wait_for(lock, 1s, [&] { return watch.executed.has_value(); })) {
      to_first_write.push_back(milliseconds(*watch.first_write - sent));
      to_execute.push_back(milliseconds(*watch.executed - sent));
    } else {
      ++missed;
    }
    watch.wanted.reset();
    lock.unlock();
    std::this_thread::sleep_for(std::chrono::milliseconds(options.interval_ms) +
                                std::chrono::microseconds(jitter_us(random)));
  }
  position.put_command(1, protocol::encode(protocol::PositionCommand{}));
  devices.shutdown_all();

  std::printf("er1_bench: ER1 emulated on %s, odometry read every 20 ms\n", robot.device_path().c_str());
  std::printf("following the robot: %.1f s, %zu cycles (%.1f /s)\n", idle_wall / 1000.0, cycles.size(),
              static_cast<double>(cycles.size()) * 1000.0 / idle_wall);
  std::printf("  driver thread CPU: %.1f us per cycle (%.2f %% of one core)\n", cpu_per_cycle_us,
              cpu_per_cycle_us * static_cast<double>(cycles.size()) / (idle_wall * 10.0));
  std::printf("commands: %d velocity commands %d-%d ms apart\n", options.commands, options.interval_ms,
              options.interval_ms + 20);
  std::printf("  put_command -> first byte on the line: p50 %.2f ms, p99 %.2f ms, max %.2f ms\n",
              percentile(to_first_write, 0.5), percentile(to_first_write, 0.99), percentile(to_first_write, 1.0));
  std::printf("  put_command -> motor 1's EXECUTE written: p50 %.2f ms, p99 %.2f ms, max %.2f ms (%zu samples, %d missed)\n",
              percentile(to_execute, 0.5), percentile(to_execute, 0.99), percentile(to_execute, 1.0),
              to_execute.size(), missed);
  return 0;
}
