#pragma once
// Sony VISCA as the EVI-D30 speaks it (sonyevid30.md §1, §2), as pure bytes:
// host -> camera `81 <message> FF`, camera -> host `90 <message> FF`; 16-bit
// values as four nibbles, most significant first. No I/O here: the driver,
// the emulator and the probe all build on these.

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "framing/terminated_packet_format.hpp"

namespace playerkit::hardware::sonyevid30 {

using Bytes = std::vector<std::uint8_t>;

inline constexpr std::uint8_t kToCamera1 = 0x81;    // 0x80 | camera address 1
inline constexpr std::uint8_t kFromCamera1 = 0x90;  // 0x80 | (address 1 << 4)
inline constexpr std::uint8_t kBroadcast = 0x88;
inline constexpr std::uint8_t kTerminator = 0xFF;
inline constexpr std::size_t kLongestMessage = 14;  // between header and terminator
inline constexpr std::size_t kLongestReply = 11;    // the pan/tilt inquiry's answer

// The EVI-D30's ranges (sheet §2.1), in the camera's units.
inline constexpr int kPanMinUnits = -880;  // 0xFC90, -100 degrees
inline constexpr int kPanMaxUnits = 880;   // 0x0370, +100 degrees
inline constexpr int kTiltMinUnits = -300; // 0xFED4, -25 degrees
inline constexpr int kTiltMaxUnits = 300;  // 0x012C, +25 degrees
inline constexpr int kZoomMaxUnits = 0x3FF;
inline constexpr int kPanSpeedMax = 0x18;
inline constexpr int kTiltSpeedMax = 0x14;

// Framing for both directions: what the camera sends, and what a host
// sends to any camera (broadcasts included), for traces and the emulator.
[[nodiscard]] framing::TerminatedPacketOptions reply_packet_options();
[[nodiscard]] framing::TerminatedPacketOptions host_packet_options();

// --- host -> camera
[[nodiscard]] Bytes to_camera(std::span<const std::uint8_t> message);  // 81 + message + FF
[[nodiscard]] Bytes pan_tilt_inquiry();                                 // 81 09 06 12 FF
[[nodiscard]] Bytes zoom_inquiry();                                     // 81 09 04 47 FF
[[nodiscard]] Bytes absolute_pan_tilt(int pan_units, int tilt_units, int pan_speed = kPanSpeedMax,
                                      int tilt_speed = kTiltSpeedMax);
enum class Drive : std::uint8_t { forward = 1, backward = 2, stop = 3 };  // pan: left/right; tilt: up/down
[[nodiscard]] Bytes drive_pan_tilt(Drive pan, Drive tilt, int pan_speed, int tilt_speed);
[[nodiscard]] Bytes zoom_direct(int zoom_units);  // clamped to 0..0x3FF
[[nodiscard]] Bytes cancel(int socket);           // 81 2y FF

// Four nibbles, most significant first, of a 16-bit value.
void put_nibbles(Bytes& out, std::uint16_t value);
// The value of four nibble bytes; nullopt if a high half is not 0.
[[nodiscard]] std::optional<std::uint16_t> read_nibbles(std::span<const std::uint8_t> four);

// --- camera -> host
struct Reply {
  enum class Kind { ack, completion, answer, error, other };
  Kind kind = Kind::other;
  int socket = 0;              // ack, completion, error
  std::uint8_t error_code = 0; // error: 02, 03, 04, 05, 41
  Bytes data;                  // answer: the bytes between `90 50` and FF
};
// One whole packet, header and terminator included.
[[nodiscard]] Reply parse_reply(std::span<const std::uint8_t> packet);
// "syntax error", "command buffer full", ... for an error code.
[[nodiscard]] std::string error_text(std::uint8_t code);

struct PanTiltUnits {
  int pan = 0;
  int tilt = 0;
};
[[nodiscard]] std::optional<PanTiltUnits> pan_tilt_answer(const Reply& reply);
[[nodiscard]] std::optional<int> zoom_answer(const Reply& reply);

// --- replies a camera sends (the emulator's, and tests' golden bytes)
[[nodiscard]] Bytes ack(int socket);
[[nodiscard]] Bytes completion(int socket);
[[nodiscard]] Bytes error_reply(int socket, std::uint8_t code);
[[nodiscard]] Bytes pan_tilt_reply(PanTiltUnits units);
[[nodiscard]] Bytes zoom_reply(int zoom_units);
[[nodiscard]] Bytes answer_reply(std::span<const std::uint8_t> data);  // 90 50 + data + FF

inline constexpr std::uint8_t kSyntaxError = 0x02;
inline constexpr std::uint8_t kBufferFull = 0x03;
inline constexpr std::uint8_t kCancelled = 0x04;
inline constexpr std::uint8_t kNoSocket = 0x05;
inline constexpr std::uint8_t kNotExecutable = 0x41;

// Bytes as "81 09 06 12 FF", for logs.
[[nodiscard]] std::string hex(std::span<const std::uint8_t> bytes);

}  // namespace playerkit::hardware::sonyevid30
