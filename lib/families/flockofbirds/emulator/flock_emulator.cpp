#include "families/flockofbirds/emulator/flock_emulator.hpp"

#include <cstdio>
#include <stdexcept>
#include <utility>

namespace playerkit::emulators {

namespace fob = hardware::flockofbirds;

FlockEmulator::FlockEmulator(FlockEmulatorOptions options) : options_(std::move(options)) {
  if (!(options_.rate_hz >= 1 && options_.rate_hz <= 1000)) {
    throw std::invalid_argument("flockofbirds emulator: the rate must be 1 to 1000 records a second");
  }
  period_ = std::chrono::duration_cast<Duration>(std::chrono::duration<double>(1.0 / options_.rate_hz));
}

void FlockEmulator::receive(std::span<const std::uint8_t> bytes, Duration now, int host_baud) {
  advance(now);
  // At the wrong speed the UART sees framing errors, not commands.
  if (options_.baud != 0 && host_baud != 0 && host_baud != options_.baud) return;
  for (const fob::BirdCommand& command : reader_.feed(bytes)) obey(command);
}

void FlockEmulator::obey(const fob::BirdCommand& command) {
  ++commands_;
  switch (command.byte) {
    case fob::CommandByte::position_angles:
      return;  // the only format emulated, and the power-up one
    case fob::CommandByte::point:
      streaming_ = false;
      send_record(now_);
      return;
    case fob::CommandByte::stream:
      if (!streaming_) next_record_ = now_;
      streaming_ = true;
      advance(now_);
      return;
    case fob::CommandByte::examine_value:
      if (command.parameter == fob::kPositionScalingParameter) {
        const auto reply = fob::scaling_reply(options_.scaling);
        output_.push_back({{reply.begin(), reply.end()}, false});
      }
      return;
    case fob::CommandByte::change_value:
      if (command.parameter == fob::kPositionScalingParameter) {
        if (const auto scaling = fob::scaling_from_reply(command.value)) options_.scaling = *scaling;
      }
      return;
  }
  // Any other byte: a command this bird does not emulate, ignored.
}

void FlockEmulator::send_record(Duration at) {
  const fob::Record record = fob::encode_record(fob::words_from_pose(options_.trajectory.at(at), options_.scaling));
  // No checksum: a bad-checksum fault leaves records alone.
  output_.push_back({{record.begin(), record.end()}, false});
  ++records_sent_;
}

void FlockEmulator::advance(Duration now) {
  if (now > now_) now_ = now;
  // Called late (a loaded machine): the records missed are skipped, not sent
  // in a burst the real bird could never produce.
  if (streaming_ && now_ - next_record_ > 5 * period_) next_record_ = now_;
  while (streaming_ && next_record_ <= now_) {
    send_record(next_record_);
    next_record_ += period_;
  }
}

Duration FlockEmulator::next_deadline() const { return streaming_ ? next_record_ : Duration::max(); }

std::vector<Telegram> FlockEmulator::take_output() { return std::exchange(output_, {}); }

void FlockEmulator::host_disconnected(Duration /*now*/) {
  // The bird knows nothing of the host: it keeps streaming if it was; only a
  // command half sent is lost with the line.
  reader_.reset();
}

std::string FlockEmulator::describe() const {
  char text[160];
  std::snprintf(text, sizeof text, "Flock of Birds, %d\" scaling, %s, %llu records, %s",
                fob::full_scale_inches(options_.scaling),
                streaming_ ? "streaming" : "point mode", static_cast<unsigned long long>(records_sent_),
                options_.trajectory.scripted() ? "scripted trajectory" : "built-in motion");
  return text;
}

}  // namespace playerkit::emulators
