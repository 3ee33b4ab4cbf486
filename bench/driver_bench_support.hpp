// What the robot-driver benchmarks (p2os, er1, trogdor, segwayrmp, nomad,
// khepera, reb, rflex) have in common: a driver on an emulated robot in
// this one process, measured in two phases.
//
//   1. follow: the robot is only followed for --seconds; CPU of the thread
//      that does the driver's work, per cycle;
//   2. commands: --commands velocity commands --interval ms apart plus a
//      random phase, each timed from Device::put_command (as the server
//      does) to its bytes on the line (the link's trace hook, right after
//      write()).
//
// A bench keeps what is its own: the emulator, the config text, how it
// counts cycles (a PublishRecorder, or its connection's own clock and
// counters through follow_connection), and the LineWatch::Matcher that knows which
// bytes mean "the command is on the line". Its main is then roughly
//
//   const BenchOptions options = parse_options(argc, argv, "x_bench");
//   emulators::EmulatorRunner robot(...);
//   DriverRig rig("x_bench", "position:0 ( driver \"x\" port \"" + ... );
//   core::Device& position = rig.device(protocol::kPositionCode);
//   LineWatch watch(position);  PublishRecorder recorder(position);
//   if (!rig.subscribe_all()) return 1;
//   const FollowResult follow = follow_publications(recorder, options);
//   const CommandRun run = run_commands(position, watch, options, 20ms,
//       [](int i) { return CommandTrial{payload for i, matcher for i}; });
//   rig.stop_and_shut_down(position, protocol::encode(PositionCommand{}));
//   print_follow(follow, "driver thread");
//   print_commands(run, "its X written");

#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/device.hpp"
#include "core/device_table.hpp"
#include "core/driver_registry.hpp"
#include "core/logger.hpp"
#include "core/server_clock.hpp"
#include "hardware_driver/robot_connection.hpp"

namespace playerkit::bench {

using SteadyClock = std::chrono::steady_clock;

struct BenchOptions {
  int seconds = 10;
  int commands = 300;
  int interval_ms = 40;
};

// An option of one bench's own beyond --seconds/--commands/--interval.
struct ExtraOption {
  std::string name;  // "--delay"
  std::function<void(int value)> set;
};

// Exits with status 2 on an unknown option, naming the ones there are.
// min_interval_ms: the benches polling every few ms accept shorter gaps.
BenchOptions parse_options(int argc, char** argv, const char* program, BenchOptions defaults = {},
                           int min_interval_ms = 5, const std::vector<ExtraOption>& extra = {});

// The calling thread's CPU clock (CLOCK_THREAD_CPUTIME_ID).
std::chrono::nanoseconds thread_cpu();

double milliseconds(std::chrono::nanoseconds d);

// Nearest rank; p = 1.0 is the maximum, 0 when there are no values.
double percentile(std::vector<double> values, double p);

// The devices of one config text on port 6665, the built-in drivers
// registered, warnings only in the log.
class DriverRig {
 public:
  DriverRig(const char* program, const std::string& config_text);
  DriverRig(const DriverRig&) = delete;
  DriverRig& operator=(const DriverRig&) = delete;

  // Exits when the config made no such device.
  core::Device& device(std::uint16_t interface_code, std::uint16_t index = 0);
  // Every device, as a client of each would; says which one failed.
  bool subscribe_all();
  // A zero command first, so the robot is left standing, then every driver
  // shut down before the figures are printed.
  void stop_and_shut_down(core::Device& device, std::span<const std::uint8_t> stop_command);

  const std::string program;
  core::ServerClock clock;
  core::Logger logger;
  core::DriverRegistry registry;
  core::DeviceTable devices;
};

// The CPU clock of the thread that publishes, read at each publication, so
// the difference between two is one cycle's work whichever thread it is.
class PublishRecorder final : public core::DeviceListener {
 public:
  explicit PublishRecorder(core::Device& device);
  PublishRecorder(const PublishRecorder&) = delete;
  PublishRecorder& operator=(const PublishRecorder&) = delete;

  void data_published(const core::Device&) override;
  void replies_ready(const core::Device&) override {}
  std::vector<std::chrono::nanoseconds> take();

 private:
  std::mutex mutex_;
  std::vector<std::chrono::nanoseconds> cpu_;
};

struct FollowResult {
  double wall_ms = 0.0;
  std::uint64_t cycles = 0;
  double cpu_per_cycle_us = 0.0;
  double core_percent = 0.0;  // of one core over the wall time
};

// Settles for half a second, then follows for options.seconds.
FollowResult follow_publications(PublishRecorder& recorder, const BenchOptions& options);
// The same where the driver keeps its own clock and cycle count (a
// connection's io_thread_cpu_time() and counters); an unknown CPU time
// gives negative figures, as it did before.
FollowResult follow_for(const BenchOptions& options,
                        const std::function<std::optional<std::chrono::nanoseconds>()>& cpu_now,
                        const std::function<std::uint64_t()>& cycles_now);

// follow_for a RobotConnection: its I/O thread's clock, and cycles as its
// counter cycle_counter over counts_per_cycle (rflex counts two motion
// reports a cycle).
FollowResult follow_connection(const hardware_driver::RobotConnection& connection, const BenchOptions& options,
                               std::string_view cycle_counter, std::uint64_t counts_per_cycle = 1);
// A connection's counter by name; 0 when it has none.
std::uint64_t counter(const hardware_driver::RobotConnection& connection, std::string_view name);

// Watches the link's outgoing bytes for one command at a time. The matcher
// runs on the writing thread under the watch's lock, so state it captures
// (an earlier step of a sequence, its time) is safe to read once wait()
// has returned.
class LineWatch {
 public:
  // true when these bytes are the command awaited on the line.
  using Matcher = std::function<bool(std::span<const std::uint8_t> bytes, SteadyClock::time_point when)>;

  // Hooks the device's byte trace; the watch must outlive the driver's use.
  explicit LineWatch(core::Device& device);
  LineWatch(const LineWatch&) = delete;
  LineWatch& operator=(const LineWatch&) = delete;

  void arm(Matcher matcher);
  // When the armed command reached the line, or nothing after timeout.
  std::optional<SteadyClock::time_point> wait(std::chrono::milliseconds timeout);

 private:
  void on_bytes(bool outgoing, std::span<const std::uint8_t> bytes, SteadyClock::time_point when);

  std::mutex mutex_;
  std::condition_variable changed_;
  Matcher matcher_;
  std::optional<SteadyClock::time_point> seen_at_;
};

struct CommandTrial {
  std::vector<std::uint8_t> payload;  // what put_command gets
  LineWatch::Matcher on_line;
};

struct CommandRun {
  int commands = 0;
  int interval_ms = 0;
  int jitter_ms = 0;
  double wall_ms = 0.0;
  std::vector<double> latencies_ms;  // put_command -> the matcher's yes
  int missed = 0;                    // not on the line within a second
  // The connection's I/O thread CPU over the run, when it was measured;
  // negative when its clock could not be read.
  std::optional<double> io_thread_cpu_ms;
};

// options.commands trials from make_trial(i), each sent at interval_ms plus
// up to max_jitter after the previous one was seen (or given up on), so
// they land at random phases of the driver's cycle. on_seen(sent) runs
// after each command that arrived, for a bench's further figures.
CommandRun run_commands(core::Device& device, LineWatch& watch, const BenchOptions& options,
                        std::chrono::milliseconds max_jitter, const std::function<CommandTrial(int i)>& make_trial,
                        const std::function<void(SteadyClock::time_point sent)>& on_seen = {});

// The same, measuring the CPU the connection's I/O thread spent meanwhile.
CommandRun run_commands(const hardware_driver::RobotConnection& connection, core::Device& device, LineWatch& watch,
                        const BenchOptions& options, std::chrono::milliseconds max_jitter,
                        const std::function<CommandTrial(int i)>& make_trial);

// "following the robot: ..." and "  <thread> CPU: ... us per cycle ...";
// cycle names what was counted ("SIP" where p2os counts SIPs).
void print_follow(const FollowResult& follow, const char* thread, const char* cycle = "cycle");
// "commands: ...", "  put_command -> <what>: p50 ... (samples, missed)"
// and, when measured, "  I/O thread CPU meanwhile: ...".
void print_commands(const CommandRun& run, const char* what);
// One more latency line in the same form, for a bench's further step.
void print_latency(const char* what, const std::vector<double>& latencies_ms, int missed);

}  // namespace playerkit::bench
