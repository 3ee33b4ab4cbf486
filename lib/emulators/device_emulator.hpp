#pragma once
// The protocol side of an emulated device, with no I/O and no clock of its
// own: bytes come in, time is advanced from outside, whole telegrams go out.
// A runner (emulator_runner.hpp) binds one to a pseudo-terminal or a TCP
// port and injects faults; tests drive it directly, byte by byte, with a
// simulated clock, so every test is deterministic.
//
// Emulators are written from the device sheets (shared/spec/devices/*.md,
// "what a faithful emulator must do"), never from our drivers: the Player 1.5
// reference driver must be able to work against them unmodified.

#include <chrono>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "algorithms/geometry/pose2.hpp"

namespace playerkit::emulators {

// Time since the emulator was created. Emulators never read a clock.
using Duration = std::chrono::nanoseconds;

// One unit of output, written to the host with a single write() (the SICK
// driver misreads telegrams split across writes). Fault injection works per
// telegram: it may corrupt the last byte (every protocol here ends in its
// checksum), cut it short, or put garbage before it.
struct Telegram {
  std::vector<std::uint8_t> bytes;
  // False for bytes that carry no checksum (the SICK ACK byte 0x06, a bare
  // text reply), which a "bad checksum" fault leaves alone.
  bool has_checksum = true;
};

class DeviceEmulator {
 public:
  DeviceEmulator() = default;
  DeviceEmulator(const DeviceEmulator&) = delete;
  DeviceEmulator& operator=(const DeviceEmulator&) = delete;
  virtual ~DeviceEmulator() = default;

  // Bytes the host wrote, in arrival order, at time `now`. `host_baud` is
  // the line speed the host had set when it wrote them (from the pty's
  // termios), or 0 when unknown (TCP): an emulator that models baud rates
  // treats bytes sent at another speed than its own as line noise.
  virtual void receive(std::span<const std::uint8_t> bytes, Duration now, int host_baud) = 0;

  // Lets time pass up to `now` (monotonic): periodic packets, motion,
  // paced streaming.
  virtual void advance(Duration now) = 0;

  // The earliest time at which advance() has something to do; the runner
  // sleeps until then or until bytes arrive. Duration::max() when idle.
  [[nodiscard]] virtual Duration next_deadline() const = 0;

  // What the device has sent since the last call, oldest first.
  virtual std::vector<Telegram> take_output() = 0;

  // The host closed its end (pty slave closed, TCP peer gone). Devices keep
  // their state across this unless their sheet says otherwise.
  virtual void host_disconnected(Duration /*now*/) {}

  // The speed the device listens at now, 0 when it does not model baud rates.
  [[nodiscard]] virtual int baud() const { return 0; }

  // A mobile base's true pose in the map, for the sensors that ride on it
  // (EmulatorMount::robot); nullopt for devices that do not move.
  [[nodiscard]] virtual std::optional<geometry::Pose2> world_pose() const { return std::nullopt; }

  // One line for logs and `--stats`: "Pioneer 3-DX, connected, 10 Hz SIPs".
  [[nodiscard]] virtual std::string describe() const = 0;
};

}  // namespace playerkit::emulators
