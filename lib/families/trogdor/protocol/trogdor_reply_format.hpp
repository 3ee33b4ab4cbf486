#pragma once
// Where the robot's replies end. Every host message is answered by one byte
// (ACK or NACK); GET_ODOM's ACK is followed by its 18-byte block, which
// nothing in the block announces, so the reader is told what it waits for.
// A NACK is always one byte. Bytes that are neither are noise.

#include <string_view>

#include "framing/frame_format.hpp"

namespace playerkit::hardware::trogdor {

enum class ReplyShape {
  ack,                 // one byte
  ack_then_odometry,   // 06 and the 18-byte block: one 19-byte telegram
  ack_then_voltage,    // 06 and the 5-byte block
  // A trace, which does not know what was asked: 06 and a block that
  // checks when the bytes are there, else the ACK alone.
  guess,
};

class TrogdorReplyFormat final : public framing::FrameFormat {
 public:
  explicit TrogdorReplyFormat(ReplyShape shape = ReplyShape::ack) : shape_(shape) {}

  // Before each exchange (same thread as the reader).
  void expect(ReplyShape shape) { shape_ = shape; }

  [[nodiscard]] std::string_view name() const override { return "trogdor"; }
  [[nodiscard]] framing::FrameScan scan(std::span<const std::uint8_t> buffered) const override;

 private:
  ReplyShape shape_;
};

// The host's messages, for traces: INIT's three bytes, 'v' and 'a' with
// their XOR, the one-byte commands; anything else one byte of noise.
class TrogdorHostFormat final : public framing::FrameFormat {
 public:
  [[nodiscard]] std::string_view name() const override { return "trogdor host"; }
  [[nodiscard]] framing::FrameScan scan(std::span<const std::uint8_t> buffered) const override;
};

// The longest reply telegram: the ACK and the odometry block.
inline constexpr std::size_t kLongestReply = 19;

}  // namespace playerkit::hardware::trogdor
