#pragma once
// The Lawicel "slcan" ASCII protocol spoken by USB-CAN adapters on a serial
// port (CANUSB, CANable, USBtin and the Linux slcan line discipline): each
// command and each received frame is a line ended by CR.
//
//   host -> adapter   "S6\r" bit rate (S0 10k ... S8 1M), "O\r" open,
//                     "C\r" close, "V\r" version, "t<id:3 hex><len:1><data:2 hex each>\r"
//                     standard frame, "T<id:8 hex><len><data>\r" extended,
//                     "r"/"R" the same without data (remote request)
//   adapter -> host   "\r" accepted, "\a" (BEL) refused, "z\r"/"Z\r" a
//                     frame sent (some adapters), received frames as above
//
// Pure text, no I/O: the CAN link (can_bus.hpp), the Segway emulator and
// the traces share it.

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "framing/can_frame.hpp"
#include "framing/frame_format.hpp"

namespace playerkit::links::can {

inline constexpr char kSlcanEnd = '\r';
inline constexpr char kSlcanRefusal = '\a';
// "T" + 8 id + 1 len + 16 data + CR: the longest frame line.
inline constexpr std::size_t kLongestSlcanLine = 27;

// The line of one frame, CR included.
[[nodiscard]] std::string slcan_frame_line(const framing::CanFrame& frame);
// A frame line without its CR; nullopt for anything else (commands, acks,
// malformed hex, a length above 8, an id beyond its width).
[[nodiscard]] std::optional<framing::CanFrame> parse_slcan_frame(std::string_view line);

// "S<n>\r" for the bit rates the protocol names (10k, 20k, 50k, 100k, 125k,
// 250k, 500k, 800k, 1M); nullopt for any other.
[[nodiscard]] std::optional<std::string> slcan_bitrate_command(int bits_per_second);
// The rate an "S<n>" code stands for; nullopt for an unknown code.
[[nodiscard]] std::optional<int> slcan_bitrate_of(char code);
[[nodiscard]] const std::vector<int>& slcan_bitrates();

inline const std::string kSlcanOpen = "O\r";
inline const std::string kSlcanClose = "C\r";
inline const std::string kSlcanVersion = "V\r";

// Adapter output cut into telegrams: a line ended by CR (an empty one is an
// acknowledgement), or a lone BEL (a refusal). LF after a CR, sent by some
// adapters, is skipped as noise.
class SlcanFormat final : public framing::FrameFormat {
 public:
  [[nodiscard]] std::string_view name() const override { return "slcan"; }
  [[nodiscard]] framing::FrameScan scan(std::span<const std::uint8_t> buffered) const override;
};

// A telegram's text without its CR ("" for an acknowledgement, "\a" for a refusal).
[[nodiscard]] std::string_view slcan_text(std::span<const std::uint8_t> telegram);

}  // namespace playerkit::links::can
