#pragma once
// Cutting ER1 traffic into telegrams. Commands say their own length through
// their opcode; replies do not (2, 4 or 6 bytes, by the command they answer),
// so the reply format is told what it waits for before each exchange.

#include <atomic>
#include <cstddef>

#include "framing/frame_format.hpp"

namespace playerkit::hardware::er1 {

// Host -> RCM: [0 or 1, checksum, 0, known opcode, argument]. The checksum
// is not part of the framing: 1.5's ACCL_3 carries a wrong one (er1.md §5.2)
// and is still a command to answer.
class CommandFormat final : public framing::FrameFormat {
 public:
  [[nodiscard]] std::string_view name() const override { return "er1 command"; }
  [[nodiscard]] framing::FrameScan scan(std::span<const std::uint8_t> buffered) const override;
};

// RCM -> host: `expected` bytes summing to 0 modulo 256.
class ReplyFormat final : public framing::FrameFormat {
 public:
  explicit ReplyFormat(std::size_t expected = 2) : expected_(expected) {}
  void expect(std::size_t size) { expected_ = size; }
  [[nodiscard]] std::string_view name() const override { return "er1 reply"; }
  [[nodiscard]] framing::FrameScan scan(std::span<const std::uint8_t> buffered) const override;

  static constexpr std::size_t kLongest = 6;

 private:
  std::atomic<std::size_t> expected_;
};

}  // namespace playerkit::hardware::er1
