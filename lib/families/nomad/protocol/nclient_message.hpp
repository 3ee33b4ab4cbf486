#pragma once
// Nomadic's Nclient messages as they travel over TCP to the Nomad server or
// the robot daemon (nomad.md §1.1): a 2-byte type, a 2-byte count of 32-bit
// words, then the words, all big-endian. Requests and replies share it.
//
// The reference's library used C `long` for words, so only its 32-bit build
// spoke this format; 4-byte words are the protocol, whatever the host.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "framing/frame_format.hpp"

namespace playerkit::hardware::nomad {

// The message types the driver and the emulator use (nomad.md §1.2).
namespace message_type {
inline constexpr std::int16_t kAccelerations = 10;     // AC
inline constexpr std::int16_t kSpeeds = 11;            // SP
inline constexpr std::int16_t kVelocityMode = 12;      // VM
inline constexpr std::int16_t kGetState = 15;          // GS
inline constexpr std::int16_t kSensorMask = 16;        // CT
inline constexpr std::int16_t kZero = 20;              // ZR
inline constexpr std::int16_t kCommandTimeout = 26;    // CONF_TM
inline constexpr std::int16_t kState = 80;             // STATE_MSG, the reply to most requests
inline constexpr std::int16_t kError = 91;             // ERROR_MSG, an error code in word 0
inline constexpr std::int16_t kConnectRobot = 102;     // CONNECT_ROBOT
inline constexpr std::int16_t kFailure = -1;           // a reply the client treats as failure
}  // namespace message_type

inline constexpr std::size_t kHeaderSize = 4;
// More words than any message of the protocol carries (a state reply with a
// full laser scan is under 1,100): a longer count is noise, not a message.
inline constexpr std::size_t kMaxWords = 2048;
inline constexpr std::size_t kMaxMessageSize = kHeaderSize + 4 * kMaxWords;

struct Message {
  std::int16_t type = 0;
  std::vector<std::int32_t> words;
  friend bool operator==(const Message&, const Message&) = default;
};

[[nodiscard]] std::vector<std::uint8_t> encode(const Message& message);

// A whole message (as the format cut it); nullopt when the count does not
// match the bytes.
[[nodiscard]] std::optional<Message> decode(std::span<const std::uint8_t> bytes);

[[nodiscard]] std::string_view type_name(std::int16_t type);

// Cuts the stream at the header's word count. There is no sync byte and no
// checksum, so the header is all there is to judge: an absurd count, or a
// type the reader does not expect, is noise (one byte dropped), which finds
// the next real header behind stray bytes.
class NclientFormat final : public framing::FrameFormat {
 public:
  // Any type.
  NclientFormat() = default;
  explicit NclientFormat(std::vector<std::int16_t> expected_types) : expected_(std::move(expected_types)) {}
  // From now on only these types (empty: any), for a reader whose next
  // replies are known.
  void expect(std::vector<std::int16_t> types) { expected_ = std::move(types); }

  [[nodiscard]] std::string_view name() const override { return "nclient"; }
  [[nodiscard]] framing::FrameScan scan(std::span<const std::uint8_t> buffered) const override;

 private:
  std::vector<std::int16_t> expected_;
};

// What a client reads once connected: a state, an error, or a failure.
[[nodiscard]] std::vector<std::int16_t> state_reply_types();

}  // namespace playerkit::hardware::nomad
