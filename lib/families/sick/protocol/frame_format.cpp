#include "families/sick/protocol/frame_format.hpp"

#include "families/sick/protocol/crc.hpp"
#include "families/sick/protocol/telegram.hpp"

#include <algorithm>

namespace playerkit::hardware::sick {

framing::FrameScan SickFrameFormat::scan(std::span<const std::uint8_t> buffered) const {
  if (buffered.empty()) return framing::FrameScan::need();
  if (buffered[0] != kStx) {
    const auto next_stx = std::find(buffered.begin() + 1, buffered.end(), kStx);
    return framing::FrameScan::noise(static_cast<std::size_t>(next_stx - buffered.begin()));
  }
  if (buffered.size() < 2) return framing::FrameScan::need(2);
  if (buffered[1] != (replies_ ? kReplyAddress : kRequestAddress)) return framing::FrameScan::noise(1);
  if (buffered.size() < kHeaderSize) return framing::FrameScan::need(kHeaderSize);

  const std::size_t length = static_cast<std::size_t>(buffered[2] | (buffered[3] << 8));
  const std::size_t shortest = replies_ ? 2 : 1;  // code + status; a command byte
  if (length < shortest || length > kMaxBodyLength) return framing::FrameScan::noise(1);

  const std::size_t size = kHeaderSize + length + kCrcSize;
  if (buffered.size() < size) return framing::FrameScan::need(size);
  const std::size_t covered = kHeaderSize + length;
  const auto sent = static_cast<std::uint16_t>(buffered[covered] | (buffered[covered + 1] << 8));
  if (sent != crc16(buffered.first(covered))) return framing::FrameScan::corrupt(size);
  return framing::FrameScan::whole(size);
}

}  // namespace playerkit::hardware::sick
