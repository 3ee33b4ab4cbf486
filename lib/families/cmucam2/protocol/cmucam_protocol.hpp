#pragma once
// The CMUcam2's ASCII protocol as pure text (cmucam2.md §1-§2): commands are
// a word and decimal arguments ended by CR; the camera answers `ACK` CR or
// `NCK` CR, maybe lines of data (a T packet, a servo position), and returns
// to idle with the prompt `:`, which has no terminator of its own.
//
// The servo commands (SV, GS) are the CMUcam2's own; the 1.5 driver had
// functions for them but never called them (cmucam2.md §2.1).

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "framing/terminated_line_format.hpp"

namespace playerkit::hardware::cmucam2 {

// The longest line worth waiting for: a T packet is at most 33 bytes
// (cmucam2.md §6.4); a version banner is shorter than this.
inline constexpr std::size_t kLongestLine = 64;
inline constexpr std::uint8_t kPrompt = ':';

// Replies are CR-ended lines, the prompt a telegram of its own.
[[nodiscard]] framing::LineOptions reply_line_options();
// Commands, for traces: CR-ended lines, the lone CR one of them.
[[nodiscard]] framing::LineOptions command_line_options();

// The colour bounds of one TC, in the camera's order: R, G, B (the manual's
// R, B, G order is wrong, cmucam2.md §4).
struct ColorBounds {
  int red_min = 16;
  int red_max = 240;
  int green_min = 16;
  int green_max = 240;
  int blue_min = 16;
  int blue_max = 240;
  [[nodiscard]] bool contains(int red, int green, int blue) const {
    return red >= red_min && red <= red_max && green >= green_min && green <= green_max && blue >= blue_min &&
           blue <= blue_max;
  }
  // Each bound 0..255, each min <= its max.
  [[nodiscard]] bool valid() const;
  // The middle of each range packed 0x00RRGGBB (blobfinder `color`).
  [[nodiscard]] std::uint32_t packed_middle() const;
  friend bool operator==(const ColorBounds&, const ColorBounds&) = default;
};

// The middle-mass T packet: `T mx my x1 y1 x2 y2 pixels confidence`.
struct TPacket {
  int mx = 0;
  int my = 0;
  int x1 = 0;
  int y1 = 0;
  int x2 = 0;
  int y2 = 0;
  int pixels = 0;
  int confidence = 0;
  friend bool operator==(const TPacket&, const TPacket&) = default;
};

// --- commands, as the text before the CR
[[nodiscard]] std::string poll_mode(bool on);                   // "PM 1"
[[nodiscard]] std::string track_color(const ColorBounds& bounds);  // "TC 200 240 16 60 16 60"
[[nodiscard]] std::string set_servo(int servo, int position);   // "SV 0 128"
[[nodiscard]] std::string get_servo(int servo);                 // "GS 0"
[[nodiscard]] std::string get_version();                        // "GV"
// A command's bytes on the wire: its text and CR ("" is the lone CR that
// stops streaming and returns the camera to idle).
[[nodiscard]] std::vector<std::uint8_t> encode(std::string_view command);

// --- replies
enum class ReplyLine { ack, nck, prompt, other };
// ACK and NCK are recognised behind line noise ("#%ACK"); so is a T packet.
[[nodiscard]] ReplyLine classify(std::string_view line);
[[nodiscard]] std::optional<TPacket> parse_t_packet(std::string_view line);
[[nodiscard]] std::string t_packet_line(const TPacket& packet);  // without the CR
// A reply line holding one decimal number (GS's answer).
[[nodiscard]] std::optional<int> parse_number(std::string_view line);

// --- commands as the camera reads them: a word and integer arguments,
// spaces anywhere (the 1.5 driver ends its commands with one).
struct ParsedCommand {
  std::string name;  // upper case
  std::vector<int> arguments;
};
[[nodiscard]] std::optional<ParsedCommand> parse_command(std::string_view text);

}  // namespace playerkit::hardware::cmucam2
