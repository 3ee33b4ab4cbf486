#pragma once
// framing::FrameFormat for P2OS frames: hunts for FA FB, rejects length
// bytes no real packet has, and reports checksum failures. The reference's
// receive-side test is weaker than intended (p2os.md §5 quirk 1); this one
// checks the full sum.

#include "framing/frame_format.hpp"
#include "families/p2os/protocol/frame.hpp"

namespace playerkit::hardware::p2os {

class P2osFrameFormat final : public framing::FrameFormat {
 public:
  // `max_length_byte`: the largest N accepted; a larger one is noise. Use
  // kMaxLengthByteToRobot when parsing what a host sends.
  explicit P2osFrameFormat(std::uint8_t max_length_byte = kMaxLengthByteFromRobot);

  [[nodiscard]] std::string_view name() const override { return "p2os"; }
  [[nodiscard]] framing::FrameScan scan(std::span<const std::uint8_t> buffered) const override;

 private:
  std::uint8_t max_length_byte_;
};

}  // namespace playerkit::hardware::p2os
