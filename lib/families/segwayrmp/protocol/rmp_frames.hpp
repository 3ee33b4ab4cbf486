#pragma once
// The Segway RMP's CAN messages (segwayrmp.md §1.1, §2) as frames: the five
// status messages the robot broadcasts (0x400-0x404), the velocity and
// status command (0x413) and the shutdown (0x412). Pure values, no I/O.
//
// Eight data bytes are four big-endian 16-bit slots; a 32-bit quantity uses
// two slots, its low half first.

#include <array>
#include <cstdint>
#include <optional>

#include "framing/can_frame.hpp"

namespace playerkit::hardware::segwayrmp {

inline constexpr std::uint32_t kBatteryId = 0x400;
inline constexpr std::uint32_t kAttitudeId = 0x401;
inline constexpr std::uint32_t kVelocityId = 0x402;
inline constexpr std::uint32_t kWheelDisplacementId = 0x403;
inline constexpr std::uint32_t kBodyDisplacementId = 0x404;
inline constexpr std::uint32_t kShutdownId = 0x412;
inline constexpr std::uint32_t kCommandId = 0x413;

// Units of the robot's counts (§2.1, §2.2).
inline constexpr double kAngleCountsPerDegree = 7.8;       // pitch, roll, their rates, yaw rate, rot command
inline constexpr double kWheelCountsPerMetrePerSecond = 332.0;
inline constexpr double kForeAftCountsPerMetre = 33215.0;
inline constexpr double kYawCountsPerRevolution = 112644.0;
inline constexpr double kTransCountsPerMillimetrePerSecond = 0.32882963;  // 1176 counts = 3576 mm/s
inline constexpr std::int16_t kMaxTransCounts = 1176;
inline constexpr std::int16_t kMaxRotCounts = 1024;

// Status command ids (§2.2).
enum class StatusCommand : std::uint16_t {
  none = 0,
  velocity_scale = 10,
  acceleration_scale = 11,
  turn_scale = 12,
  gain_schedule = 13,
  current_limit = 14,
  reset_integrators = 50,
};
// Bits of reset_integrators' value.
inline constexpr std::uint8_t kResetRightWheel = 1;
inline constexpr std::uint8_t kResetLeftWheel = 2;
inline constexpr std::uint8_t kResetYaw = 4;
inline constexpr std::uint8_t kResetForeAft = 8;
inline constexpr std::uint8_t kResetAll = 0x0F;

// What one 0x413 frame carries.
struct Command {
  std::int16_t trans = 0;  // counts, ±kMaxTransCounts
  std::int16_t rot = 0;    // counts, ±kMaxRotCounts, counter-clockwise positive as the host sends it
  StatusCommand status = StatusCommand::none;
  std::uint8_t status_value = 0;  // only the low byte travels (bytes 6 and 7)
  friend bool operator==(const Command&, const Command&) = default;
};

[[nodiscard]] framing::CanFrame command_frame(const Command& command);
[[nodiscard]] framing::CanFrame shutdown_frame();
// A 0x413 frame's command; nullopt for any other frame.
[[nodiscard]] std::optional<Command> parse_command(const framing::CanFrame& frame);

// Velocity counts for speeds in the Player units (mm/s, deg/s), already
// within the caller's limits: rounded, then clamped to what the RMP takes.
[[nodiscard]] std::int16_t trans_counts(double millimetres_per_second);
[[nodiscard]] std::int16_t rot_counts(double degrees_per_second);

// Everything the five status messages carry, in counts.
struct Status {
  std::uint16_t battery = 0;  // 0x400 slot 2
  std::int16_t pitch = 0;
  std::int16_t pitch_rate = 0;
  std::int16_t roll = 0;
  std::int16_t roll_rate = 0;
  std::int16_t left_wheel_velocity = 0;
  std::int16_t right_wheel_velocity = 0;
  std::int16_t yaw_rate = 0;  // clockwise positive
  std::uint16_t frame_counter = 0;
  std::uint32_t left_wheel_displacement = 0;
  std::uint32_t right_wheel_displacement = 0;
  std::uint32_t fore_aft_displacement = 0;
  std::uint32_t yaw_displacement = 0;  // counter-clockwise grows
  friend bool operator==(const Status&, const Status&) = default;
};

[[nodiscard]] std::array<framing::CanFrame, 5> status_frames(const Status& status);

// Gathers the five status messages into one Status. A set is complete
// when one message of each id 0x400-0x404 has arrived since the last one
// (as 1.5 counted them); other ids are ignored.
class StatusAssembler {
 public:
  // True when `frame` completed a set: status() is then the new one.
  bool add(const framing::CanFrame& frame);
  [[nodiscard]] const Status& status() const { return status_; }
  void clear() { seen_ = 0; }

 private:
  Status status_;
  std::uint8_t seen_ = 0;  // bit (id & 0xF) per message since the last complete set
};

}  // namespace playerkit::hardware::segwayrmp
