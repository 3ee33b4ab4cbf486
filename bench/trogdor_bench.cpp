// trogdor against the emulated O-Bot on a pseudo-terminal, in this one
// process:
//
//  * CPU of the driver's thread per cycle (its thread CPU clock at each
//    publication): one GET_ODOM exchange and the odometry, every 15 ms,
//    while the robot is only followed;
//  * latency from a velocity command written to the device
//    (Device::put_command, as the server does) to its SET_VELOCITIES on the
//    line (the link's trace hook, right after write()), p50 and p99 over
//    --commands commands, each asking for other wheel units.
//
//   ./build/bench/trogdor_bench [--seconds 10] [--commands 300] [--interval 40]
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
#include "families/trogdor/emulator/trogdor_emulator.hpp"
#include "families/trogdor/protocol/trogdor_messages.hpp"
#include "families/trogdor/protocol/trogdor_units.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/position.hpp"

namespace {

using namespace playerkit;
using namespace std::chrono_literals;
using SteadyClock = std::chrono::steady_clock;
namespace hw = hardware::trogdor;

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
      std::fprintf(stderr, "trogdor_bench: unknown option %s (--seconds, --commands, --interval)\n", name.c_str());
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

// When the SET_VELOCITIES awaited went out.
struct CommandWatch {
  std::mutex mutex;
  std::condition_variable changed;
  std::optional<hw::Bytes> wanted;
  std::optional<SteadyClock::time_point> written;

  void on_bytes(bool outgoing, std::span<const std::uint8_t> bytes, SteadyClock::time_point when) {
    if (!outgoing) return;
    std::lock_guard lock(mutex);
    if (!wanted || written || !std::equal(bytes.begin(), bytes.end(), wanted->begin(), wanted->end())) return;
    written = when;
    changed.notify_all();
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
  emulators::EmulatorRunner robot(std::make_unique<emulators::TrogdorEmulator>(emulators::TrogdorEmulatorOptions{}, nullptr),
                                  emulators::PtyEndpoint{});

  core::ServerClock clock;
  core::Logger logger("trogdor_bench");
  logger.set_level(core::LogLevel::kWarning);
  core::DriverRegistry registry;
  drivers::register_builtin_drivers(registry);
  core::DeviceTable devices;
  const std::string text = "position:0 ( driver \"trogdor\" port \"" + robot.device_path() + "\" )\n";
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
    std::fprintf(stderr, "trogdor_bench: the driver did not set up\n");
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
  std::vector<double> latencies;
  int missed = 0;
  std::mt19937 random(1);
  std::uniform_int_distribution<int> jitter_us(0, 15000);
  for (int i = 0; i < options.commands; ++i) {
    protocol::PositionCommand command;
    command.xspeed = 100 + 40 * (i % 10);  // 100 ... 460 mm/s: 7 ... 30 units, never the previous ones
    {
      std::lock_guard lock(watch.mutex);
      watch.wanted = hw::set_velocities(hw::wheel_units_for(command.xspeed, 0));
      watch.written.reset();
    }
    const auto sent = SteadyClock::now();
    position.put_command(1, protocol::encode(command));
    std::unique_lock lock(watch.mutex);
    if (watch.changed.wait_for(lock, 1s, [&] { return watch.written.has_value(); })) {
      latencies.push_back(milliseconds(*watch.written - sent));
    } else {
      ++missed;
    }
    lock.unlock();
    std::this_thread::sleep_for(std::chrono::milliseconds(options.interval_ms) + std::chrono::microseconds(jitter_us(random)));
  }
  position.unsubscribe();

  std::printf("following: %zu cycles in %.0f ms (%.1f Hz), driver thread CPU %.1f us per cycle\n", cycles.size(),
              idle_wall, static_cast<double>(cycles.size()) * 1000.0 / idle_wall, cpu_per_cycle_us);
  std::printf("command -> SET_VELOCITIES on the line: p50 %.3f ms, p99 %.3f ms, max %.3f ms (%zu commands, %d missed)\n",
              percentile(latencies, 0.5), percentile(latencies, 0.99), percentile(latencies, 1.0), latencies.size(),
              missed);
  return missed == 0 ? 0 : 1;
}
