// The nomad driver against the emulated Nomad 200 behind its server on a
// loopback TCP port, in this one process:
//
//  * CPU of the driver's thread per cycle (its thread CPU clock, read by a
//    listener the driver calls after each publication): one VM and one GS
//    exchange, every 50 ms, while the robot is only followed;
//  * latency from a velocity command written to the device
//    (Device::put_command, as the server does) to the VM carrying it on the
//    link (the link's trace hook, right after write()), p50 and p99 over
//    --commands commands, each another speed so its bytes are told apart.
//
//   ./build/bench/nomad_bench [--seconds 10] [--commands 300] [--interval 40] [--delay 20]
//
// --delay is the emulated server's reply time in ms (nomad.md §6: 10-50).
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
#include "families/nomad/emulator/nomad_emulator.hpp"
#include "families/nomad/protocol/nclient_message.hpp"
#include "families/nomad/protocol/nomad_units.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/nomad.hpp"

namespace {

using namespace playerkit;
using namespace std::chrono_literals;
using SteadyClock = std::chrono::steady_clock;
namespace nomad = hardware::nomad;

struct Options {
  int seconds = 10;
  int commands = 300;
  int interval_ms = 40;
  int delay_ms = 20;
};

Options parse(int argc, char** argv) {
  Options options;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string name = argv[i];
    const int value = std::atoi(argv[i + 1]);
    if (name == "--seconds") options.seconds = std::max(1, value);
    else if (name == "--commands") options.commands = std::max(10, value);
    else if (name == "--interval") options.interval_ms = std::max(5, value);
    else if (name == "--delay") options.delay_ms = std::clamp(value, 0, 1000);
    else {
      std::fprintf(stderr, "nomad_bench: unknown option %s (--seconds, --commands, --interval, --delay)\n",
                   name.c_str());
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

// When the VM with the awaited translation word was written.
struct CommandWatch {
  std::mutex mutex;
  std::condition_variable changed;
  std::optional<std::int32_t> wanted;
  std::optional<SteadyClock::time_point> written;

  void on_bytes(bool outgoing, std::span<const std::uint8_t> bytes, SteadyClock::time_point when) {
    if (!outgoing) return;
    const auto message = nomad::decode(bytes);
    if (!message || message->type != nomad::message_type::kVelocityMode || message->words.empty()) return;
    std::lock_guard lock(mutex);
    if (wanted && !written && message->words[0] == *wanted) {
      written = when;
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
  emulators::NomadEmulatorOptions robot_options;
  robot_options.reply_delay = std::chrono::milliseconds(options.delay_ms);
  emulators::EmulatorRunner robot(std::make_unique<emulators::NomadEmulator>(robot_options), emulators::TcpEndpoint{});

  core::ServerClock clock;
  core::Logger logger("nomad_bench");
  logger.set_level(core::LogLevel::kWarning);
  core::DriverRegistry registry;
  drivers::register_builtin_drivers(registry);
  core::DeviceTable devices;
  const std::string text = "nomad:0 ( driver \"nomad\" port \"" + robot.device_path() + "\" )\n";
  core::instantiate_devices(config::ConfigFile::parse(text, "bench.cfg", core::load_options_for(registry, 6665)),
                            registry, devices, clock, logger);
  core::Device& device = *devices.find(6665, {protocol::kNomadCode, 0});

  CommandWatch watch;
  device.driver().set_byte_trace([&watch](bool outgoing, std::span<const std::uint8_t> bytes,
                                          SteadyClock::time_point when) { watch.on_bytes(outgoing, bytes, when); });
  PublishRecorder recorder;
  device.add_listener(&recorder);
  if (!device.subscribe()) {
    std::fprintf(stderr, "nomad_bench: the driver did not set up\n");
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

  // 2. Commands at random phases of the cycle.
  std::vector<double> to_vm;
  int missed = 0;
  std::mt19937 random(1);
  std::uniform_int_distribution<int> jitter_us(0, 20000);
  for (int i = 0; i < options.commands; ++i) {
    protocol::NomadCommand command;
    command.vel_trans = 10 * (1 + i % 40);  // 10 ... 400 mm/s, never the previous one
    {
      std::lock_guard lock(watch.mutex);
      watch.wanted = nomad::tenth_inches_from_mm(command.vel_trans);
      watch.written.reset();
    }
    const auto sent = SteadyClock::now();
    device.put_command(1, protocol::encode(command));
    std::unique_lock lock(watch.mutex);
    if (watch.changed.wait_for(lock, 1s, [&] { return watch.written.has_value(); })) {
      to_vm.push_back(milliseconds(*watch.written - sent));
    } else {
      ++missed;
    }
    watch.wanted.reset();
    lock.unlock();
    std::this_thread::sleep_for(std::chrono::milliseconds(options.interval_ms) +
                                std::chrono::microseconds(jitter_us(random)));
  }
  device.put_command(1, protocol::encode(protocol::NomadCommand{}));
  devices.shutdown_all();

  std::printf("nomad_bench: Nomad 200 emulated behind its server on %s, replies after %d ms\n",
              robot.device_path().c_str(), options.delay_ms);
  std::printf("following the robot: %.1f s, %zu cycles (%.1f /s)\n", idle_wall / 1000.0, cycles.size(),
              static_cast<double>(cycles.size()) * 1000.0 / idle_wall);
  std::printf("  driver thread CPU: %.1f us per cycle (%.2f %% of one core)\n", cpu_per_cycle_us,
              cpu_per_cycle_us * static_cast<double>(cycles.size()) / (idle_wall * 10.0));
  std::printf("commands: %d velocity commands %d-%d ms apart\n", options.commands, options.interval_ms,
              options.interval_ms + 20);
  std::printf("  put_command -> its VM written: p50 %.2f ms, p99 %.2f ms, max %.2f ms (%zu samples, %d missed)\n",
              percentile(to_vm, 0.5), percentile(to_vm, 0.99), percentile(to_vm, 1.0), to_vm.size(), missed);
  return 0;
}
