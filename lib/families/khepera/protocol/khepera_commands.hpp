#pragma once
// The Khepera BIOS ("SerCom") command set as the 1.5 drivers used it
// (khepera.md §1.1, §2): a command is an upper-case letter, a comma before
// each decimal argument, and LF; the reply is the same letter in lower case
// with its values, ended by CR LF. No checksum.
//
//   D,l,r  set the wheel speeds (pulses per 10 ms)     -> d
//   E      read the wheel speeds                       -> e,l,r
//   G,l,r  set the position counters (pulses)          -> g
//   H      read the position counters                  -> h,l,r
//   N      read the proximity (IR) sensors, 0..1023    -> n,v0,...,v7

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "framing/terminated_line_format.hpp"

namespace playerkit::hardware::khepera {

// A command or a reply: its letter and its integers.
struct Message {
  char letter = 0;
  std::vector<std::int64_t> values;
  friend bool operator==(const Message&, const Message&) = default;
};

namespace letter {
inline constexpr char set_speed = 'D';
inline constexpr char read_speed = 'E';
inline constexpr char set_position = 'G';
inline constexpr char read_position = 'H';
inline constexpr char read_proximity = 'N';
}  // namespace letter

// The BIOS's wheel speeds are signed bytes of pulses per 10 ms.
inline constexpr int kFastestWheel = 127;
// The longest line worth waiting for: N with 32 sensors of four digits.
inline constexpr std::size_t kLongestLine = 200;

[[nodiscard]] Message set_speed(std::int64_t left, std::int64_t right);
[[nodiscard]] Message read_speed();
[[nodiscard]] Message set_position(std::int64_t left, std::int64_t right);
[[nodiscard]] Message read_position();
[[nodiscard]] Message read_proximity();

// "D,8,-8\n".
[[nodiscard]] std::vector<std::uint8_t> encode_command(const Message& command);
// "e,8,-8\r\n": the command's letter in lower case.
[[nodiscard]] std::vector<std::uint8_t> encode_reply(const Message& reply);

// A line's text (terminator removed; a stray CR kept by a canonical tty is
// dropped too) as a message: a letter, then ",<integer>" for each value.
// Nothing for anything else (an empty line, noise, a value that is no
// integer, a trailing comma).
[[nodiscard]] std::optional<Message> parse_line(std::string_view text);

// The reply to `command`: its letter in lower case with `count` values
// (nullopt: any number). Nothing for any other line.
[[nodiscard]] std::optional<Message> parse_reply_to(char command, std::string_view text,
                                                    std::optional<std::size_t> count);

// The same, behind noise on its line (bytes of a noisy cable land inside
// lines, where no line format can tell them from text): the reply is the
// last part of the line that reads as one.
[[nodiscard]] std::optional<Message> find_reply_to(char command, std::string_view text,
                                                   std::optional<std::size_t> count);

// Replies end in CR LF, commands in LF; both are read as lines ended by CR
// or LF (a canonical tty kept the CR as data: it never matters here), and
// the empty lines a start-up CR LF leaves are noise.
[[nodiscard]] framing::LineOptions reply_line_options();
[[nodiscard]] framing::LineOptions command_line_options();

}  // namespace playerkit::hardware::khepera
