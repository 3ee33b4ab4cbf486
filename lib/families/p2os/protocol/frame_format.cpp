#include "families/p2os/protocol/frame_format.hpp"

#include <algorithm>

namespace playerkit::hardware::p2os {

P2osFrameFormat::P2osFrameFormat(std::uint8_t max_length_byte)
    : max_length_byte_(std::max(max_length_byte, kMinLengthByte)) {}

framing::FrameScan P2osFrameFormat::scan(std::span<const std::uint8_t> buffered) const {
  if (buffered.empty()) return framing::FrameScan::need();
  if (buffered[0] != kHeader1) {
    const auto next = std::find(buffered.begin() + 1, buffered.end(), kHeader1);
    return framing::FrameScan::noise(static_cast<std::size_t>(next - buffered.begin()));
  }
  if (buffered.size() < 2) return framing::FrameScan::need(2);
  if (buffered[1] != kHeader2) return framing::FrameScan::noise(1);
  if (buffered.size() < kHeaderSize) return framing::FrameScan::need(kHeaderSize);
  const std::uint8_t length = buffered[2];
  // Dropping only the FA lets the hunt look inside a bogus header's bytes.
  if (length < kMinLengthByte || length > max_length_byte_) return framing::FrameScan::noise(1);
  const std::size_t total = kHeaderSize + length;
  if (buffered.size() < total) return framing::FrameScan::need(total);
  const auto payload = buffered.subspan(kHeaderSize, length - kChecksumSize);
  const std::uint16_t sent =
      static_cast<std::uint16_t>((buffered[total - 2] << 8) | buffered[total - 1]);
  return sent == checksum(payload) ? framing::FrameScan::whole(total) : framing::FrameScan::corrupt(total);
}

}  // namespace playerkit::hardware::p2os
