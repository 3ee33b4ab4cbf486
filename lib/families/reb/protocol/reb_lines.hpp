#pragma once
// The REB's LPRSerCom command lines and replies as text (reb.md §1.1, §2):
// a command is an upper-case letter and comma-separated decimal arguments
// ended by CR ("D,2,-24\r"); its reply the lower-case letter and values
// ended by CR LF ("h,12345\r\n"), followed by the prompt ":\r\n".

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "framing/terminated_line_format.hpp"

namespace playerkit::hardware::reb {

// The board's motor numbers (reb.md §2): the right wheel's motor faces the
// other way, so it turns negated for forward motion.
enum class Motor : int { right = 0, left = 2 };

// The A/D channel wired to the battery.
inline constexpr int kBatteryChannel = 15;
// 1.5 read reply lines of up to 63 characters; a W line of 32 readings fits.
inline constexpr std::size_t kLongestLine = 256;

struct Command {
  char letter = 0;  // upper case
  std::vector<std::int32_t> arguments;
  friend bool operator==(const Command&, const Command&) = default;
};

struct Reply {
  char letter = 0;  // lower case
  std::vector<std::int32_t> values;
  friend bool operator==(const Reply&, const Reply&) = default;
};

// "D,2,-24\r"
[[nodiscard]] std::vector<std::uint8_t> encode(const Command& command);
// "D,2,-24" (no CR) as the board reads it; nothing for a line that is not
// an upper-case letter followed by comma-separated integers.
[[nodiscard]] std::optional<Command> parse_command(std::string_view line);

// "h,12345" (no terminator)
[[nodiscard]] std::string reply_text(const Reply& reply);
// A reply line's text without its terminator; nothing for the prompt, for
// noise, or for values that are not integers.
[[nodiscard]] std::optional<Reply> parse_reply(std::string_view line);
// The reply to a command answered with `letter` in a line that may begin
// with line noise: the first place the letter starts a whole reply.
[[nodiscard]] std::optional<Reply> find_reply(std::string_view line, char letter);
// The prompt ":" the firmware writes after each reply (noise before it allowed).
[[nodiscard]] bool is_prompt(std::string_view line);
// The reply letter a command is answered with.
[[nodiscard]] char reply_letter(char command_letter);

// The commands the driver sends (reb.md §2).
[[nodiscard]] Command set_speed(Motor motor, std::int32_t pulses_per_10ms);      // D
[[nodiscard]] Command read_speed(Motor motor);                                   // E
[[nodiscard]] Command move_to(Motor motor, std::int32_t position);               // C
[[nodiscard]] Command set_position(Motor motor, std::int32_t position);          // G
[[nodiscard]] Command read_position(Motor motor);                                // H
[[nodiscard]] Command read_motion_status(Motor motor);                           // K
[[nodiscard]] Command speed_pid(Motor motor, std::int32_t kp, std::int32_t ki, std::int32_t kd);     // A
[[nodiscard]] Command position_pid(Motor motor, std::int32_t kp, std::int32_t ki, std::int32_t kd);  // F
[[nodiscard]] Command speed_profile(Motor motor, std::int32_t speed, std::int32_t acceleration);      // J
[[nodiscard]] Command read_analog(int channel);                                                     // I
[[nodiscard]] Command read_ir();                                                                    // W
[[nodiscard]] Command ir_power(bool on);                                                            // Y

// Replies arrive as lines ended by CR LF; commands end in CR.
[[nodiscard]] framing::LineOptions reply_line_options();
[[nodiscard]] framing::LineOptions command_line_options();

}  // namespace playerkit::hardware::reb
