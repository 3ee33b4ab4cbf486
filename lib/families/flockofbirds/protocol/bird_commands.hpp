#pragma once
// The Flock of Birds' RS-232 commands the driver uses (flockofbirds.md §2):
// single command bytes, EXAMINE VALUE and CHANGE VALUE followed by their
// parameter bytes, no terminator. And the bird's side: a reader that splits
// a byte stream into those commands, however it was cut.

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "families/flockofbirds/protocol/bird_record.hpp"
#include "framing/fixed_length_format.hpp"

namespace playerkit::hardware::flockofbirds {

enum class CommandByte : std::uint8_t {
  point = 0x42,            // 'B': one record now (also ends STREAM)
  stream = 0x40,           // '@': records continuously
  position_angles = 0x59,  // 'Y': POSITION/ANGLES records
  examine_value = 0x4F,    // 'O' + parameter number: its value back
  change_value = 0x50,     // 'P' + parameter number + value bytes
};

inline constexpr std::uint8_t kPositionScalingParameter = 3;
// EXAMINE VALUE of the position scaling answers one word, LS byte first.
inline constexpr std::size_t kScalingReplySize = 2;

[[nodiscard]] std::vector<std::uint8_t> command(CommandByte byte);
[[nodiscard]] std::vector<std::uint8_t> examine_position_scaling();  // 4F 03
[[nodiscard]] std::vector<std::uint8_t> change_position_scaling(PositionScaling scaling);  // 50 03 lo hi

// The bird's answer to EXAMINE VALUE 3: 00 00 (36") or 01 00 (72").
[[nodiscard]] std::array<std::uint8_t, kScalingReplySize> scaling_reply(PositionScaling scaling);
// What the answer says: 0 is 36", 1 is 72", anything else nullopt.
[[nodiscard]] std::optional<PositionScaling> scaling_from_reply(std::span<const std::uint8_t> reply);
// A value answer is two bytes without the phasing bit (a record's first
// byte in their place fails the check and is dropped).
[[nodiscard]] framing::FixedLengthOptions scaling_reply_format_options();

// One command as the bird reads it.
struct BirdCommand {
  CommandByte byte = CommandByte::point;  // or any other byte, which the bird ignores
  std::uint8_t raw = 0;                   // the command byte as received
  std::uint8_t parameter = 0;             // EXAMINE and CHANGE VALUE
  std::vector<std::uint8_t> value;        // CHANGE VALUE's value bytes
  friend bool operator==(const BirdCommand&, const BirdCommand&) = default;
};

// The bird's command parser: EXAMINE VALUE takes one parameter byte after
// it, CHANGE VALUE a parameter byte and that parameter's value bytes (two:
// every parameter playerkit knows is one word). Bytes may come in any pieces.
class CommandReader {
 public:
  // The commands completed by `bytes`, in order.
  std::vector<BirdCommand> feed(std::span<const std::uint8_t> bytes);
  // Forgets a command half received (the host went away).
  void reset();

 private:
  std::optional<BirdCommand> pending_;
  bool have_parameter_ = false;
};

}  // namespace playerkit::hardware::flockofbirds
