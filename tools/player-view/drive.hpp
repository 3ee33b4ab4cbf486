#pragma once
// --drive: what the pages ask of the robot's base, with the dead-man rule.
// Pure (messages and times in, commands out), so the rule is unit-tested.
//
// A page sends {"type":"drive","x":X,"yaw":YAW} (each -1, 0 or 1: arrow keys
// or the on-screen pad) while a key is held, again every 0.2 s, and
// {"type":"stop"} when it is released or the page loses focus. The robot
// stops when the page driving it says stop, closes, or falls silent for
// `hold` seconds (a frozen tab, a lost network): it never keeps going on a
// message that is not renewed. {"type":"motors","on":true|false} (the
// page's buttons) asks for the motors' power; switching them off stops too.

#include <cstdint>
#include <optional>
#include <string_view>
#include <utility>

namespace playerkit::player_view {

struct DriveCommand {
  double forward = 0;  // m/s
  double turn = 0;     // rad/s, counter-clockwise
  friend bool operator==(const DriveCommand&, const DriveCommand&) = default;
};

class DriveControl {
 public:
  DriveControl(double speed, double turn_rate, double hold = 0.6)
      : speed_(speed), turn_rate_(turn_rate), hold_(hold) {}

  // A page's message; anything that is not a drive or stop message is ignored.
  void message(std::uint64_t page, std::string_view text, double now);
  void closed(std::uint64_t page);
  // The command to send now when it differs from the last one sent (the
  // first non-zero one also means "motors on"); nullopt otherwise.
  std::optional<DriveCommand> update(double now);
  // Whether the next command sent is the first since the robot stood still
  // (the caller switches the motors on then).
  [[nodiscard]] bool starting() const { return sent_ == DriveCommand{}; }
  // The motor power a page asked for since the last call, if any.
  std::optional<bool> take_motor_request() { return std::exchange(motor_request_, std::nullopt); }

 private:
  void stop() { wanted_ = {}; driver_.reset(); }

  double speed_, turn_rate_, hold_;
  std::optional<std::uint64_t> driver_;  // the page driving now
  double last_heard_ = 0;
  DriveCommand wanted_;
  DriveCommand sent_;
  std::optional<bool> motor_request_;
};

}  // namespace playerkit::player_view
