#include "driver_bench_support.hpp"

#include <time.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <thread>
#include <utility>

#include "config/config_file.hpp"
#include "core/instantiate.hpp"
#include "drivers/builtin.hpp"

namespace playerkit::bench {

using namespace std::chrono_literals;

BenchOptions parse_options(int argc, char** argv, const char* program, BenchOptions defaults, int min_interval_ms,
                           const std::vector<ExtraOption>& extra) {
  BenchOptions options = defaults;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string name = argv[i];
    const int value = std::atoi(argv[i + 1]);
    if (name == "--seconds") {
      options.seconds = std::max(1, value);
      continue;
    }
    if (name == "--commands") {
      options.commands = std::max(10, value);
      continue;
    }
    if (name == "--interval") {
      options.interval_ms = std::max(min_interval_ms, value);
      continue;
    }
    const auto own = std::find_if(extra.begin(), extra.end(), [&](const ExtraOption& o) { return o.name == name; });
    if (own != extra.end()) {
      own->set(value);
      continue;
    }
    std::string known = "--seconds, --commands, --interval";
    for (const ExtraOption& o : extra) known += ", " + o.name;
    std::fprintf(stderr, "%s: unknown option %s (%s)\n", program, name.c_str(), known.c_str());
    std::exit(2);
  }
  return options;
}

std::chrono::nanoseconds thread_cpu() {
  timespec cpu{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &cpu);
  return std::chrono::seconds(cpu.tv_sec) + std::chrono::nanoseconds(cpu.tv_nsec);
}

double milliseconds(std::chrono::nanoseconds d) { return std::chrono::duration<double, std::milli>(d).count(); }

double percentile(std::vector<double> values, double p) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const auto index = static_cast<std::size_t>(p * static_cast<double>(values.size() - 1) + 0.5);
  return values[std::min(index, values.size() - 1)];
}

DriverRig::DriverRig(const char* program_name, const std::string& config_text)
    : program(program_name), logger(program_name) {
  logger.set_level(core::LogLevel::kWarning);
  drivers::register_builtin_drivers(registry);
  core::instantiate_devices(
      config::ConfigFile::parse(config_text, "bench.cfg", core::load_options_for(registry, 6665)), registry, devices,
      clock, logger);
}

core::Device& DriverRig::device(std::uint16_t interface_code, std::uint16_t index) {
  core::Device* device = devices.find(6665, {interface_code, index});
  if (device == nullptr) {
    std::fprintf(stderr, "%s: the config made no device %u:%u\n", program.c_str(), interface_code, index);
    std::exit(1);
  }
  return *device;
}

bool DriverRig::subscribe_all() {
  for (core::Device* device : devices.all()) {
    if (!device->subscribe()) {
      std::fprintf(stderr, "%s: %s could not be subscribed\n", program.c_str(), device->name().c_str());
      return false;
    }
  }
  return true;
}

void DriverRig::stop_and_shut_down(core::Device& device, std::span<const std::uint8_t> stop_command) {
  device.put_command(1, stop_command);
  devices.shutdown_all();
}

PublishRecorder::PublishRecorder(core::Device& device) { device.add_listener(this); }

void PublishRecorder::data_published(const core::Device&) {
  const auto cpu = thread_cpu();
  std::lock_guard lock(mutex_);
  cpu_.push_back(cpu);
}

std::vector<std::chrono::nanoseconds> PublishRecorder::take() {
  std::lock_guard lock(mutex_);
  return std::exchange(cpu_, {});
}

FollowResult follow_publications(PublishRecorder& recorder, const BenchOptions& options) {
  std::this_thread::sleep_for(500ms);
  (void)recorder.take();
  const auto wall_before = SteadyClock::now();
  std::this_thread::sleep_for(std::chrono::seconds(options.seconds));
  FollowResult result;
  result.wall_ms = milliseconds(SteadyClock::now() - wall_before);
  const auto cycles = recorder.take();
  result.cycles = cycles.size();
  // Between the first and the last publication there are size - 1 cycles.
  if (cycles.size() > 1) {
    result.cpu_per_cycle_us = std::chrono::duration<double, std::micro>(cycles.back() - cycles.front()).count() /
                              static_cast<double>(cycles.size() - 1);
  }
  result.core_percent = result.cpu_per_cycle_us * static_cast<double>(result.cycles) / (result.wall_ms * 10.0);
  return result;
}

FollowResult follow_for(const BenchOptions& options,
                        const std::function<std::optional<std::chrono::nanoseconds>()>& cpu_now,
                        const std::function<std::uint64_t()>& cycles_now) {
  std::this_thread::sleep_for(500ms);
  const auto cpu_before = cpu_now();
  const auto cycles_before = cycles_now();
  const auto wall_before = SteadyClock::now();
  std::this_thread::sleep_for(std::chrono::seconds(options.seconds));
  const auto cpu_after = cpu_now();
  FollowResult result;
  result.wall_ms = milliseconds(SteadyClock::now() - wall_before);
  result.cycles = cycles_now() - cycles_before;
  const double cpu_ms = cpu_before && cpu_after ? milliseconds(*cpu_after - *cpu_before) : -1.0;
  result.core_percent = 100.0 * cpu_ms / result.wall_ms;
  if (result.cycles > 0) result.cpu_per_cycle_us = 1000.0 * cpu_ms / static_cast<double>(result.cycles);
  return result;
}

std::uint64_t counter(const hardware_driver::RobotConnection& connection, std::string_view name) {
  for (const auto& c : connection.counters()) {
    if (c.name == name) return c.value;
  }
  return 0;
}

FollowResult follow_connection(const hardware_driver::RobotConnection& connection, const BenchOptions& options,
                               std::string_view cycle_counter, std::uint64_t counts_per_cycle) {
  return follow_for(
      options, [&connection] { return connection.io_thread_cpu_time(); },
      [&] { return counter(connection, cycle_counter) / counts_per_cycle; });
}

LineWatch::LineWatch(core::Device& device) {
  device.driver().set_byte_trace(
      [this](bool outgoing, std::span<const std::uint8_t> bytes, SteadyClock::time_point when) {
        on_bytes(outgoing, bytes, when);
      });
}

void LineWatch::arm(Matcher matcher) {
  std::lock_guard lock(mutex_);
  matcher_ = std::move(matcher);
  seen_at_.reset();
}

std::optional<SteadyClock::time_point> LineWatch::wait(std::chrono::milliseconds timeout) {
  std::unique_lock lock(mutex_);
  changed_.wait_for(lock, timeout, [this] { return seen_at_.has_value(); });
  // Disarmed: a late match must not be taken for the next command's.
  matcher_ = nullptr;
  return seen_at_;
}

void LineWatch::on_bytes(bool outgoing, std::span<const std::uint8_t> bytes, SteadyClock::time_point when) {
  if (!outgoing) return;
  std::lock_guard lock(mutex_);
  if (!matcher_ || seen_at_ || !matcher_(bytes, when)) return;
  seen_at_ = when;
  changed_.notify_all();
}

CommandRun run_commands(core::Device& device, LineWatch& watch, const BenchOptions& options,
                        std::chrono::milliseconds max_jitter, const std::function<CommandTrial(int i)>& make_trial,
                        const std::function<void(SteadyClock::time_point sent)>& on_seen) {
  CommandRun run;
  run.commands = options.commands;
  run.interval_ms = options.interval_ms;
  run.jitter_ms = static_cast<int>(max_jitter.count());
  // Seeded: every run sends the same phases.
  std::mt19937 random(1);
  std::uniform_int_distribution<int> jitter_us(0, static_cast<int>(max_jitter.count()) * 1000);
  const auto wall_before = SteadyClock::now();
  for (int i = 0; i < options.commands; ++i) {
    CommandTrial trial = make_trial(i);
    watch.arm(std::move(trial.on_line));
    const auto sent = SteadyClock::now();
    device.put_command(1, trial.payload);
    if (const auto seen = watch.wait(1s)) {
      run.latencies_ms.push_back(milliseconds(*seen - sent));
      if (on_seen) on_seen(sent);
    } else {
      ++run.missed;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(options.interval_ms) +
                                std::chrono::microseconds(jitter_us(random)));
  }
  run.wall_ms = milliseconds(SteadyClock::now() - wall_before);
  return run;
}

CommandRun run_commands(const hardware_driver::RobotConnection& connection, core::Device& device, LineWatch& watch,
                        const BenchOptions& options, std::chrono::milliseconds max_jitter,
                        const std::function<CommandTrial(int i)>& make_trial) {
  const auto before = connection.io_thread_cpu_time();
  CommandRun run = run_commands(device, watch, options, max_jitter, make_trial);
  const auto after = connection.io_thread_cpu_time();
  run.io_thread_cpu_ms = before && after ? milliseconds(*after - *before) : -1.0;
  return run;
}

void print_follow(const FollowResult& follow, const char* thread, const char* cycle) {
  std::printf("following the robot: %.1f s, %llu %ss (%.1f /s)\n", follow.wall_ms / 1000.0,
              static_cast<unsigned long long>(follow.cycles), cycle,
              static_cast<double>(follow.cycles) * 1000.0 / follow.wall_ms);
  std::printf("  %s CPU: %.1f us per %s (%.2f %% of one core)\n", thread, follow.cpu_per_cycle_us, cycle,
              follow.core_percent);
}

void print_latency(const char* what, const std::vector<double>& latencies_ms, int missed) {
  std::printf("  put_command -> %s: p50 %.2f ms, p99 %.2f ms, max %.2f ms (%zu samples, %d missed)\n", what,
              percentile(latencies_ms, 0.5), percentile(latencies_ms, 0.99), percentile(latencies_ms, 1.0),
              latencies_ms.size(), missed);
}

void print_commands(const CommandRun& run, const char* what) {
  std::printf("commands: %d velocity commands %d-%d ms apart, %.1f s\n", run.commands, run.interval_ms,
              run.interval_ms + run.jitter_ms, run.wall_ms / 1000.0);
  print_latency(what, run.latencies_ms, run.missed);
  if (run.io_thread_cpu_ms) {
    std::printf("  I/O thread CPU meanwhile: %.1f ms (%.2f %% of one core)\n", *run.io_thread_cpu_ms,
                100.0 * *run.io_thread_cpu_ms / run.wall_ms);
  }
}

}  // namespace playerkit::bench
