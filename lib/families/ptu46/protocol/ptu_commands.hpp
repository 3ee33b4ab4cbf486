#pragma once
// The PTU-46's ASCII commands (ptu46.md §2): a letter for the axis, a letter
// for the quantity, an optional decimal argument, then a delimiter. Pure
// bytes; the unit accepts either case, and a space, CR or LF as delimiter.
//
//   encode(set_position(Axis::pan, 583))  -> "pp583 "
//   encode(query(Axis::tilt, Quantity::resolution)) -> "tr "

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace playerkit::hardware::ptu46 {

enum class Axis { pan, tilt };

// What a two-letter command names after its axis letter.
enum class Quantity {
  position,      // P: absolute position, in positions
  speed,         // S: desired speed, positions/s (signed in pure-velocity mode)
  resolution,    // R: arc-seconds per position (query only)
  min_position,  // N: lowest position allowed (query only)
  max_position,  // X: highest position allowed (query only)
  lower_speed,   // L: lowest speed allowed, positions/s
  upper_speed,   // U: highest speed allowed, positions/s
};

enum class ControlMode {
  independent,    // CI: each axis goes to its position at its speed
  pure_velocity,  // CV: the signed speed drives the axis
};

// One command's text, without its delimiter ("pp583", "ft", "r").
struct Command {
  std::string text;
  friend bool operator==(const Command&, const Command&) = default;
};

[[nodiscard]] Command query(Axis axis, Quantity quantity);
[[nodiscard]] Command set_position(Axis axis, std::int64_t positions);
[[nodiscard]] Command set_speed(Axis axis, std::int64_t positions_per_second);
[[nodiscard]] Command set_control_mode(ControlMode mode);
[[nodiscard]] Command terse_feedback();  // FT: queries answer "* <number>" only
[[nodiscard]] Command echo_off();        // ED
[[nodiscard]] Command reset();           // R: recalibrates both axes
// A lone delimiter: ends whatever a previous session left half typed.
[[nodiscard]] Command empty();

// The text followed by one space, as the reference driver sends it.
[[nodiscard]] std::vector<std::uint8_t> encode(const Command& command);

// A command as the unit reads it: letters folded to lower case, then split
// into its name ("pp", "ci", "r") and its argument if it has digits after
// the name. nullopt for text that is no command shape at all.
struct ParsedCommand {
  std::string name;
  std::optional<std::int64_t> argument;
  friend bool operator==(const ParsedCommand&, const ParsedCommand&) = default;
};
[[nodiscard]] std::optional<ParsedCommand> parse_command(std::string_view text);

[[nodiscard]] char axis_letter(Axis axis);
[[nodiscard]] std::string_view axis_name(Axis axis);  // "Pan", "Tilt" (the unit's messages)

}  // namespace playerkit::hardware::ptu46
