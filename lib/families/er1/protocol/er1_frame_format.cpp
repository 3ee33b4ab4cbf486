#include "families/er1/protocol/er1_frame_format.hpp"

#include "families/er1/protocol/er1_commands.hpp"

namespace playerkit::hardware::er1 {

framing::FrameScan CommandFormat::scan(std::span<const std::uint8_t> buffered) const {
  if (buffered.empty()) return framing::FrameScan::need(1);
  if (buffered[0] > 1) return framing::FrameScan::noise(1);
  if (buffered.size() < 3) return framing::FrameScan::need(buffered.size() + 1);
  if (buffered[2] != 0) return framing::FrameScan::noise(1);
  if (buffered.size() < 4) return framing::FrameScan::need(4);
  const std::size_t length = command_length(buffered[3]);
  if (length == 0) return framing::FrameScan::noise(1);
  if (buffered.size() < length) return framing::FrameScan::need(length);
  return framing::FrameScan::whole(length);
}

framing::FrameScan ReplyFormat::scan(std::span<const std::uint8_t> buffered) const {
  const std::size_t size = expected_.load();
  if (buffered.size() < size) return framing::FrameScan::need(size);
  return sums_to_zero(buffered.first(size)) ? framing::FrameScan::whole(size) : framing::FrameScan::corrupt(size);
}

}  // namespace playerkit::hardware::er1
