#pragma once
// Puts a DeviceEmulator on a line a driver can open: a pseudo-terminal
// (optionally behind a symlink such as /tmp/ttyPIONEER) or a TCP port on
// loopback. A thread of its own moves bytes between the line and the
// emulator, advances the emulator's time and applies the fault plan; each
// telegram goes out with one write().
//
//   emulators::EmulatorRunner robot(std::make_unique<P2osRobotEmulator>(options),
//                                   emulators::PtyEndpoint{});
//   config: position:0 ( driver "p2os_position" port "<robot.device_path()>" )
//   robot.with_emulator<P2osRobotEmulator>([](auto& e) { return e.true_pose(); });

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <variant>
#include <vector>

#include "emulators/device_emulator.hpp"
#include "emulators/runner/fault_injector.hpp"
#include "emulators/runner/fault_plan.hpp"

namespace playerkit::links {
class PseudoTerminal;
class TcpListener;
}  // namespace playerkit::links

namespace playerkit::emulators {

struct PtyEndpoint {
  std::optional<std::filesystem::path> symlink;  // a stable name for the driver's `port`
};
struct TcpEndpoint {
  std::string host = "127.0.0.1";
  std::uint16_t port = 0;  // 0: a free port chosen by the kernel
};
using Endpoint = std::variant<PtyEndpoint, TcpEndpoint>;

struct RunnerStats {
  std::uint64_t bytes_in = 0;   // host -> device, as received (before the line-dead check)
  std::uint64_t bytes_out = 0;  // device -> host, as written (faults included)
  std::uint64_t telegrams_out = 0;
  std::uint64_t host_connects = 0;
  std::uint64_t host_disconnects = 0;
  InjectedFaults faults;
};

class EmulatorRunner {
 public:
  // Opens the line and starts the thread. Throws links::LinkError when the
  // pty or the port cannot be had.
  EmulatorRunner(std::unique_ptr<DeviceEmulator> emulator, const Endpoint& endpoint, FaultPlan faults = {});
  EmulatorRunner(const EmulatorRunner&) = delete;
  EmulatorRunner& operator=(const EmulatorRunner&) = delete;
  ~EmulatorRunner();  // stops the thread, closes the line

  // What a driver's `port` option should say: the symlink or /dev/pts/N, or
  // "tcp:127.0.0.1:PORT".
  [[nodiscard]] const std::string& device_path() const { return device_path_; }
  // The time the emulator has been running (its clock).
  [[nodiscard]] Duration now() const;
  [[nodiscard]] RunnerStats stats() const;

  // Runs `action` with the emulator, its thread held off meanwhile (tests
  // reading a true pose; a laser's pose source reading the robot it rides on).
  template <class Emulator, class Action>
  auto with_emulator(Action&& action) {
    std::lock_guard lock(mutex_);
    return action(dynamic_cast<Emulator&>(*emulator_));
  }

  // Stops the thread now (idempotent). The line stays open until destruction.
  void stop();

 private:
  void run_pty();
  void run_tcp();
  // Feeds received bytes and advances time; returns what to write, one
  // write() per chunk (faults applied). Written outside the lock, since a
  // write may wait on a host that does not read.
  std::vector<std::vector<std::uint8_t>> exchange(std::span<const std::uint8_t> received, int host_baud);
  void host_came();
  void host_left();
  // When the thread should look again: the emulator's next deadline, but at
  // least every 50 ms so that stop() is noticed.
  [[nodiscard]] std::chrono::steady_clock::time_point next_wake() const;

  std::unique_ptr<DeviceEmulator> emulator_;
  FaultInjector faults_;
  std::unique_ptr<links::PseudoTerminal> pty_;
  std::unique_ptr<links::TcpListener> listener_;
  std::string device_path_;
  const std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();

  mutable std::mutex mutex_;  // the emulator, the injector and stats_
  RunnerStats stats_;
  std::optional<Duration> host_opened_at_;  // for a slow start, which begins at every open
  std::atomic<bool> stopping_{false};
  std::thread thread_;
};

}  // namespace playerkit::emulators
