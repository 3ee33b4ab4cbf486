// rmpposition against the emulated Segway RMP behind an slcan adapter on a
// pseudo-terminal, in this one process:
//
//  * CPU of the driver's I/O thread per cycle (its thread CPU clock, read by
//    a listener the driver calls at each publication): one status set of
//    five slcan frames parsed, the odometry, a publication and one 0x413
//    velocity frame written, 100 times a second (the RMP's native rate);
//  * latency from a velocity command written to the device
//    (Device::put_command, as the server does) to the 0x413 frame carrying
//    it on the line (the link's trace hook, right after write()), p50 and
//    p99 over --commands commands. Each command asks for another speed, so
//    its frame is told apart. The driver answers each status set, as 1.5
//    did, so up to one period (10 ms) of this is the bus's pace.
//
//   ./build/bench/segwayrmp_bench [--seconds 10] [--commands 300] [--interval 40]
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
#include <string_view>
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
#include "families/segwayrmp/emulator/segwayrmp_emulator.hpp"
#include "families/segwayrmp/protocol/rmp_frames.hpp"
#include "links/can/slcan.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/position.hpp"

namespace {

using namespace playerkit;
using namespace std::chrono_literals;
using SteadyClock = std::chrono::steady_clock;
namespace rmp = hardware::segwayrmp;

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
      std::fprintf(stderr, "segwayrmp_bench: unknown option %s (--seconds, --commands, --interval)\n", name.c_str());
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

// The first 0x413 line carrying the translation awaited.
struct CommandWatch {
  std::mutex mutex;
  std::condition_variable changed;
  std::optional<std::int16_t> wanted;
  std::optional<SteadyClock::time_point> written;

  void on_bytes(bool outgoing, std::span<const std::uint8_t> bytes, SteadyClock::time_point when) {
    if (!outgoing) return;
    const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    const auto frame = links::can::parse_slcan_frame(text.substr(0, text.find('\r')));
    if (!frame) return;
    const auto command = rmp::parse_command(*frame);
    std::lock_guard lock(mutex);
    if (!command || !wanted || written || command->trans != *wanted) return;
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

bool enable_motors(core::Device& position) {
  (void)position.take_replies();
  const auto payload = protocol::encode(protocol::PositionPowerConfig{protocol::kPositionMotorPowerReq, 1});
  if (position.enqueue_request(core::Request{1, position.address(), payload, {}}) !=
      core::Device::RequestStatus::kQueued) {
    return false;
  }
  const auto give_up = SteadyClock::now() + 5s;
  while (SteadyClock::now() < give_up) {
    for (const core::Reply& reply : position.take_replies()) return reply.type == protocol::MessageType::kAck;
    std::this_thread::sleep_for(5ms);
  }
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  const Options options = parse(argc, argv);
  emulators::EmulatorRunner robot(std::make_unique<emulators::SegwayRmpEmulator>(), emulators::PtyEndpoint{});

  core::ServerClock clock;
  core::Logger logger("segwayrmp_bench");
  logger.set_level(core::LogLevel::kWarning);
  core::DriverRegistry registry;
  drivers::register_builtin_drivers(registry);
  core::DeviceTable devices;
  const std::string text = "position:0 ( driver \"rmpposition\" canio \"slcan\" port \"" + robot.device_path() +
                           "\" max_xspeed 1000 command_timeout 1 )\n";
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
  if (!position.subscribe() || !enable_motors(position)) {
    std::fprintf(stderr, "segwayrmp_bench: the driver did not set up\n");
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
  std::vector<double> latency;
  int missed = 0;
  std::mt19937 random(1);
  std::uniform_int_distribution<int> jitter_us(0, 20000);
  for (int i = 0; i < options.commands; ++i) {
    protocol::PositionCommand command;
    command.xspeed = 10 + 10 * (i % 40);  // 10 ... 400 mm/s, never the previous one
    {
      std::lock_guard lock(watch.mutex);
      watch.wanted = rmp::trans_counts(command.xspeed);
      watch.written.reset();
    }
    const auto sent = SteadyClock::now();
    position.put_command(1, protocol::encode(command));
    std::unique_lock lock(watch.mutex);
    if (watch.changed.wait_for(lock, 1s, [&] { return watch.written.has_value(); })) {
      latency.push_back(milliseconds(*watch.written - sent));
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

  std::printf("segwayrmp_bench: Segway RMP emulated behind slcan on %s, status sets at 100 Hz\n",
              robot.device_path().c_str());
  std::printf("following the robot: %.1f s, %zu cycles (%.1f /s)\n", idle_wall / 1000.0, cycles.size(),
              static_cast<double>(cycles.size()) * 1000.0 / idle_wall);
  std::printf("  I/O thread CPU: %.1f us per cycle (%.2f %% of one core)\n", cpu_per_cycle_us,
              cpu_per_cycle_us * static_cast<double>(cycles.size()) / (idle_wall * 10.0));
  std::printf("commands: %d velocity commands %d-%d ms apart\n", options.commands, options.interval_ms,
              options.interval_ms + 20);
  std::printf("  put_command -> its 0x413 frame written: p50 %.2f ms, p99 %.2f ms, max %.2f ms (%zu samples, %d missed)\n",
              percentile(latency, 0.5), percentile(latency, 0.99), percentile(latency, 1.0), latency.size(), missed);
  return 0;
}
