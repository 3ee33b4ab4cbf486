#pragma once
// An emulated Ascension Flock of Birds (one bird, stand-alone RS-232),
// written from flockofbirds.md §6 ("what a faithful emulator must do"), so
// that Player 1.5's flockofbirds driver works against it unmodified:
//
//  * every byte is a command; EXAMINE VALUE ('O') takes one parameter byte,
//    CHANGE VALUE ('P') a parameter byte and two value bytes;
//  * 'Y' selects POSITION/ANGLES records (the power-up format); no reply;
//  * 'B' ends a stream and sends one record at once, in one write;
//  * 'O' 3 answers the position scaling, 00 00 (36") or 01 00 (72");
//    'P' 3 changes it;
//  * '@' streams records at the measurement rate, each written whole;
//  * records as §1.1: the phasing bit on byte 0 only, words clamped;
//  * nothing else: no echo, no banner, no reply to other parameters.
//
// The pose comes from a BirdTrajectory on the emulator's clock. Bytes the
// host sends at another line speed than the bird's are noise to it.

#include <cstdint>
#include <string>
#include <vector>

#include "emulators/device_emulator.hpp"
#include "families/flockofbirds/emulator/bird_trajectory.hpp"
#include "families/flockofbirds/protocol/bird_commands.hpp"

namespace playerkit::emulators {

struct FlockEmulatorOptions {
  BirdTrajectory trajectory;  // default: the built-in motion
  hardware::flockofbirds::PositionScaling scaling = hardware::flockofbirds::PositionScaling::inches_36;
  double rate_hz = 100;  // records a second while streaming (the bird's measurement rate)
  int baud = 115200;     // the bird's switches; 0: any speed
};

class FlockEmulator final : public DeviceEmulator {
 public:
  // Throws std::invalid_argument for a rate outside 1..1000 Hz.
  explicit FlockEmulator(FlockEmulatorOptions options = {});

  void receive(std::span<const std::uint8_t> bytes, Duration now, int host_baud) override;
  void advance(Duration now) override;
  [[nodiscard]] Duration next_deadline() const override;
  std::vector<Telegram> take_output() override;
  void host_disconnected(Duration now) override;
  [[nodiscard]] int baud() const override { return options_.baud; }
  [[nodiscard]] std::string describe() const override;

  // For tests and `--stats`.
  [[nodiscard]] bool streaming() const { return streaming_; }
  [[nodiscard]] hardware::flockofbirds::PositionScaling scaling() const { return options_.scaling; }
  [[nodiscard]] hardware::flockofbirds::BirdPose pose_at(Duration now) const { return options_.trajectory.at(now); }
  [[nodiscard]] std::uint64_t records_sent() const { return records_sent_; }
  [[nodiscard]] std::uint64_t commands() const { return commands_; }

 private:
  void obey(const hardware::flockofbirds::BirdCommand& command);
  void send_record(Duration at);

  FlockEmulatorOptions options_;
  Duration period_;
  hardware::flockofbirds::CommandReader reader_;
  bool streaming_ = false;
  Duration now_{0};
  Duration next_record_{0};
  std::vector<Telegram> output_;
  std::uint64_t records_sent_ = 0;
  std::uint64_t commands_ = 0;
};

}  // namespace playerkit::emulators
