#pragma once
// SICK LMS 2xx / PLS telegrams as bytes (sicklms200.md §1.2, sickpls.md §1):
//
//   host -> device   02 00 LEN(LE) command params...        CRC(LE)
//   device -> host   02 80 LEN(LE) code data... status      CRC(LE)
//
// LEN counts the body (everything between LEN and the CRC); a reply's body
// ends in a status byte that LEN and the CRC cover. Both directions share the
// CRC of crc.hpp. Besides telegrams, a device sends lone bytes: ACK 0x06
// before a reply, NAK 0x15 for a corrupt request.

#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace playerkit::hardware::sick {

inline constexpr std::uint8_t kStx = 0x02;
inline constexpr std::uint8_t kRequestAddress = 0x00;  // the device, as every driver here addresses it
inline constexpr std::uint8_t kReplyAddress = 0x80;    // the host, in every reply
inline constexpr std::uint8_t kAck = 0x06;
inline constexpr std::uint8_t kNak = 0x15;
// The status byte seen in typical replies; drivers do not interpret it.
inline constexpr std::uint8_t kStatusOk = 0x10;

inline constexpr std::size_t kHeaderSize = 4;  // STX, address, LEN
inline constexpr std::size_t kCrcSize = 2;
// The longest body either side accepts. The longest real one is a 401-value
// B7 scan (810 bytes); the reference driver's data buffer is 1024 bytes.
inline constexpr std::size_t kMaxBodyLength = 1024;

// Bytes that do not form the telegram or message they claim to: a clear
// message naming what was being read and the sizes involved.
class TelegramError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A device's reply, unwrapped: code (command + 0x80, or 0x92), data, status.
struct Reply {
  std::uint8_t code = 0;
  std::vector<std::uint8_t> data;
  std::uint8_t status = kStatusOk;

  friend bool operator==(const Reply&, const Reply&) = default;
};

// Wraps a body (command byte and parameters) into a whole host telegram.
// Throws TelegramError for an empty body or one over kMaxBodyLength.
std::vector<std::uint8_t> frame_request(std::span<const std::uint8_t> body);

// Wraps a reply into a whole device telegram.
std::vector<std::uint8_t> frame_reply(const Reply& reply);
std::vector<std::uint8_t> frame_reply(std::uint8_t code, std::span<const std::uint8_t> data,
                                      std::uint8_t status = kStatusOk);

// The body of one whole host telegram (as a SickFrameFormat reported it),
// checked again: STX, address 0x00, LEN matching the size, CRC. Throws
// TelegramError naming the first thing that is wrong.
std::vector<std::uint8_t> unframe_request(std::span<const std::uint8_t> telegram);

// The same for one whole device telegram (address 0x80, body of code and
// status at least).
Reply unframe_reply(std::span<const std::uint8_t> telegram);

// "02 80 03 00": for error messages and traces.
std::string hex(std::span<const std::uint8_t> bytes, std::size_t max_bytes = 16);

}  // namespace playerkit::hardware::sick
